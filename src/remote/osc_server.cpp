#include "remote/osc_server.h"

#include "remote/osc_dispatch.h"
#include "remote/osc_packet.h"
#include "remote/socket_address.h"

#include <fmt/format.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace vitrine::remote {

OscServer::OscServer(const BindAddress& bind, const Catalogue& catalogue, RemoteInbox& inbox, RemoteStats& stats,
                     OscLimits limits, OscAccess access)
    : OscServer(bind, catalogue, inbox, stats, limits, std::make_shared<OscTrust>(std::move(access))) {}

OscServer::OscServer(const BindAddress& bind, const Catalogue& catalogue, RemoteInbox& inbox, RemoteStats& stats,
                     OscLimits limits, std::shared_ptr<OscTrust> trust)
    : catalogue_(catalogue), inbox_(inbox), stats_(stats), limits_(limits), budgets_(limits.perSender),
      trust_(std::move(trust)),
      buffer_(limits.maxDatagram + 1) {
  const SocketAddress address = socketAddress(bind);
  const auto failed = [&](std::string_view what) {
    const std::string why = std::strerror(errno);
    if (socket_ >= 0) ::close(socket_);
    if (wake_ >= 0) ::close(wake_);
    return std::runtime_error(fmt::format("Cannot {} OSC on UDP {}: {}", what, formatBind(bind), why));
  };
  socket_ = ::socket(address.family, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) throw failed("open a socket for");
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address.storage), address.length) != 0)
    throw failed("listen for");
  sockaddr_storage bound{};
  socklen_t length = sizeof bound;
  if (::getsockname(socket_, reinterpret_cast<sockaddr*>(&bound), &length) != 0) throw failed("read the port of");
  port_ = ntohs(bound.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6&>(bound).sin6_port
                                            : reinterpret_cast<sockaddr_in&>(bound).sin_port);
  wake_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  if (wake_ < 0) throw failed("make a wake-up for");
  thread_ = std::thread([this] { run(); });
}

OscServer::~OscServer() {
  const uint64_t one = 1;
  [[maybe_unused]] const ssize_t written = ::write(wake_, &one, sizeof one);
  thread_.join();
  ::close(socket_);
  ::close(wake_);
}

void OscServer::run() {
  pollfd fds[2] = {{socket_, POLLIN, 0}, {wake_, POLLIN, 0}};
  while (true) {
    const int ready = ::poll(fds, 2, -1);
    if (ready < 0 && errno != EINTR) return;  // cannot happen with valid descriptors; never spin
    if (fds[1].revents) return;
    if (fds[0].revents & POLLIN) receive();
  }
}

void OscServer::receive() {
  // One byte more than allowed, and MSG_TRUNC to learn the real length of a larger datagram.
  std::vector<std::byte>& buffer = buffer_;
  sockaddr_storage peer{};
  socklen_t peerLength = sizeof peer;
  const ssize_t length = ::recvfrom(socket_, buffer.data(), buffer.size(), MSG_TRUNC | MSG_DONTWAIT,
                                    reinterpret_cast<sockaddr*>(&peer), &peerLength);
  if (length < 0) return;  // EAGAIN, or an ICMP error reported on the socket: nothing to read
  if (size_t(length) > limits_.maxDatagram) {
    count(stats_.oversized);
    return;
  }
  const std::string sender = peerHost(peer);
  std::vector<std::span<const std::byte>> messages;
  std::string error;
  if (!splitOscPacket(std::span(buffer.data(), size_t(length)), messages, error)) {
    count(stats_.malformed);
    return;
  }
  for (const auto& message : messages) handleMessage(message, sender);
}

void OscServer::handleMessage(std::span<const std::byte> bytes, const std::string& sender) {
  if (!budgets_.take(sender)) {
    count(stats_.rateLimited);
    return;
  }
  OscMessage message;
  std::string error;
  if (!decodeOscMessage(bytes, message, error)) {
    count(stats_.malformed);
    return;
  }
  if (!trust_->allowed(sender)) {
    if (message.path == "/vitrine/token" && message.args.size() == 1 && message.args[0].type == 's' &&
        trust_->offer(sender, message.args[0].text)) {
      count(stats_.accepted);
    } else {
      count(stats_.unauthorised);
    }
    return;
  }
  dispatchOsc(message, "osc " + sender, catalogue_, inbox_, stats_);
}

}  // namespace vitrine::remote
