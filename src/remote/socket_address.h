#pragma once
// Small POSIX socket helpers shared by the OSC server and its tests.
#include "remote/bind_address.h"

#include <sys/socket.h>

#include <string>

namespace vitrine::remote {

// The numeric address of a bind, ready for bind(2); throws std::runtime_error when it is not one.
struct SocketAddress {
  sockaddr_storage storage{};
  socklen_t length = 0;
  int family = AF_INET;
};
SocketAddress socketAddress(const BindAddress& bind);

// "127.0.0.1" / "::1": a peer's address without its port, as a rate limiter's key.
std::string peerHost(const sockaddr_storage& peer);

// This machine's first IPv4 address that is up and not loopback ("192.168.1.20"), for the URL a
// phone opens when the server listens on every interface; "127.0.0.1" when there is none.
std::string networkAddress();

}  // namespace vitrine::remote
