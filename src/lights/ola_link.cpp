#include "lights/ola_link.h"

#include <ola/Callback.h>
#include <ola/DmxBuffer.h>
#include <ola/Logging.h>
#include <ola/client/ClientArgs.h>
#include <ola/client/OlaClient.h>
#include <ola/io/SelectServer.h>
#include <ola/network/IPV4Address.h>
#include <ola/network/SocketAddress.h>
#include <ola/network/TCPSocket.h>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace vitrine::lights {

struct OlaLink::Impl {
  uint16_t port;
  Received received;
  ola::io::SelectServer server;
  std::unique_ptr<ola::network::TCPSocket> socket;
  std::unique_ptr<ola::client::OlaClient> client;
  std::vector<uint32_t> listened;
  bool closed = false;
  uint64_t sent = 0, acknowledged = 0;

  void close() {
    if (socket && socket->ValidReadDescriptor()) server.RemoveReadDescriptor(socket.get());
    if (client) client->Stop();
    client.reset();
    if (socket) socket->Close();
    socket.reset();
    listened.clear();
  }

  void onDmx(const ola::client::DMXMetadata& metadata, const ola::DmxBuffer& buffer) {
    if (received) received(metadata.universe, buffer.GetRaw(), std::min<size_t>(buffer.Size(), kUniverseChannels));
  }
};

OlaLink::OlaLink(uint16_t port, Received received) : impl_(std::make_unique<Impl>()) {
  // OLA warns on stderr at every refused connection: a line every retry. Vitrine says the state itself.
  static std::once_flag logging;
  std::call_once(logging, [] { ola::InitLogging(ola::OLA_LOG_FATAL, ola::OLA_LOG_STDERR); });
  impl_->port = port;
  impl_->received = std::move(received);
}

OlaLink::~OlaLink() { impl_->close(); }

std::string OlaLink::connect() {
  impl_->close();
  impl_->closed = false;
  impl_->sent = impl_->acknowledged = 0;
  const ola::network::IPV4SocketAddress address(ola::network::IPV4Address::Loopback(), impl_->port);
  impl_->socket.reset(ola::network::TCPSocket::Connect(address));
  if (!impl_->socket) return "nothing answers on 127.0.0.1:" + std::to_string(impl_->port);
  impl_->socket->SetNoDelay();
  impl_->client = std::make_unique<ola::client::OlaClient>(impl_->socket.get());
  if (!impl_->client->Setup()) {
    impl_->close();
    return "the OLA client did not start";
  }
  Impl* impl = impl_.get();
  impl_->client->SetCloseHandler(ola::NewSingleCallback(+[](Impl* self) { self->closed = true; }, impl));
  impl_->client->SetDMXCallback(ola::NewCallback(impl, &Impl::onDmx));
  impl_->server.AddReadDescriptor(impl_->socket.get());
  return {};
}

bool OlaLink::connected() const { return impl_->client != nullptr && !impl_->closed; }

void OlaLink::listen(const std::vector<uint32_t>& universes) {
  if (!connected()) return;
  for (uint32_t universe : impl_->listened)
    if (std::find(universes.begin(), universes.end(), universe) == universes.end())
      impl_->client->RegisterUniverse(universe, ola::client::UNREGISTER, nullptr);
  for (uint32_t universe : universes)
    if (std::find(impl_->listened.begin(), impl_->listened.end(), universe) == impl_->listened.end())
      impl_->client->RegisterUniverse(universe, ola::client::REGISTER, nullptr);
  impl_->listened = universes;
}

void OlaLink::send(uint32_t universe, const Universe& channels) {
  if (!connected()) return;
  ola::DmxBuffer buffer(channels.data(), static_cast<unsigned int>(channels.size()));
  // Answered, so a run that ends after its last frame knows olad has it (a socket closed with olad's
  // answers unread is reset, and olad may drop what it had not read yet).
  ola::client::SendDMXArgs args(ola::NewSingleCallback(+[](Impl* self, const ola::client::Result&) { ++self->acknowledged; }, impl_.get()));
  impl_->client->SendDMX(universe, buffer, args);
  ++impl_->sent;
}

uint64_t OlaLink::sent() const { return impl_->sent; }
uint64_t OlaLink::acknowledged() const { return impl_->acknowledged; }

bool OlaLink::pump(double seconds) {
  if (!connected()) return false;
  const auto micros = int64_t(std::max(0.0, seconds) * 1e6);
  impl_->server.RunOnce(ola::TimeInterval(int32_t(micros / 1000000), int32_t(micros % 1000000)));
  if (impl_->closed) impl_->close();
  return connected();
}

void OlaLink::disconnect() { impl_->close(); }

}  // namespace vitrine::lights
