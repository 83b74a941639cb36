#include "remote/socket_session.h"

#include "remote/messages.h"
#include "remote/osc_dispatch.h"
#include "remote/osc_packet.h"
#include "remote/oscquery.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace vitrine::remote {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

SocketSession::SocketSession(beast::tcp_stream&& stream, WebHub& hub, ConnectionSlot slot, bool oscQuery)
    : socket_(std::move(stream)), hub_(hub), slot_(std::move(slot)), budget_(hub.limits.perSocket),
      oscQuery_(oscQuery), stream_(hub.limits.stream), flushTimer_(socket_.get_executor()) {
  ++hub_.sockets;
  beast::error_code ignored;
  const auto peer = beast::get_lowest_layer(socket_).socket().remote_endpoint(ignored);
  // An OSCQuery client's refusals go to the console, as OSC's do: it has no reply channel for them.
  client_ = fmt::format("{} {}:{}", oscQuery ? "oscquery" : "ws", peer.address().to_string(ignored), peer.port());
}

SocketSession::~SocketSession() {
  hub_.openSockets.erase(this);
  hub_.querySockets.erase(this);
  --hub_.sockets;
}

void SocketSession::accept(beast::http::request<beast::http::string_body> request) {
  // The WebSocket's own timers replace the HTTP deadline: a handshake limit, then pings when idle
  // and a close when a ping goes unanswered.
  beast::get_lowest_layer(socket_).expires_never();
  websocket::stream_base::timeout timeout{};
  timeout.handshake_timeout = hub_.limits.requestTimeout;
  timeout.idle_timeout = hub_.limits.socketIdle;
  timeout.keep_alive_pings = true;
  socket_.set_option(timeout);
  socket_.read_message_max(hub_.limits.maxSocketMessage);
  socket_.auto_fragment(false);
  socket_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& response) { response.set(beast::http::field::server, "vitrine"); }));
  socket_.async_accept(request, beast::bind_front_handler(&SocketSession::onAccept, shared_from_this()));
}

void SocketSession::onAccept(beast::error_code error) {
  if (error) return;
  open_ = true;
  socket_.text(true);
  if (oscQuery_) {
    hub_.querySockets.insert(this);
  } else {
    hub_.openSockets.insert(this);
    if (hub_.lastState) sendState(hub_.lastState);
  }
  read();
}

void SocketSession::read() {
  socket_.async_read(buffer_, beast::bind_front_handler(&SocketSession::onRead, shared_from_this()));
}

void SocketSession::onRead(beast::error_code error, size_t) {
  if (error == websocket::error::message_too_big || error == websocket::error::buffer_overflow) {
    // Beast has already failed the connection with "message too big"; the session ends here.
    count(hub_.stats.oversized);
    return;
  }
  if (error) return;  // closed, timed out, or a protocol violation: the session ends
  const auto data = buffer_.cdata();
  const std::string_view bytes(static_cast<const char*>(data.data()), data.size());
  if (!budget_.take()) {
    count(hub_.stats.rateLimited);
  } else if (oscQuery_) {
    if (socket_.got_text()) handleQueryCommand(bytes);
    else handleOsc(bytes);
  } else if (!socket_.got_text()) {
    count(hub_.stats.malformed);
    reply(R"({"type":"refused","reason":"send text messages of JSON"})");
  } else {
    handle(bytes);
  }
  buffer_.consume(buffer_.size());
  read();
}

void SocketSession::refuse(const std::string& reason) {
  reply(nlohmann::json{{"type", "refused"}, {"reason", reason}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

void SocketSession::handle(std::string_view text) {
  const auto refuse = [&](std::atomic<uint64_t>& counter, const std::string& why) {
    count(counter);
    this->refuse(why);
  };
  ParseResult parsed = parseSocketMessage(text);
  if (!parsed.command) return refuse(hub_.stats.malformed, parsed.error);
  if (std::string why = hub_.catalogue.check(*parsed.command); !why.empty()) return refuse(hub_.stats.refused, why);
  parsed.command->client = client_;
  if (hub_.inbox.push(std::move(*parsed.command))) count(hub_.stats.accepted);
  else refuse(hub_.stats.dropped, "the gallery is busy; try again");
}

void SocketSession::handleQueryCommand(std::string_view text) {
  const auto command = parseStreamCommand(text);
  if (!command) return count(hub_.stats.malformed);
  if (!command->listen) {
    stream_.ignore(command->path);
    return count(hub_.stats.accepted);
  }
  if (!listenable(hub_.catalogue.scenes(), command->path) || !stream_.listen(command->path))
    return count(hub_.stats.refused);  // no such value, or this socket listens to as many as it may
  count(hub_.stats.accepted);
}

void SocketSession::handleOsc(std::string_view bytes) {
  const std::span packet(reinterpret_cast<const std::byte*>(bytes.data()), bytes.size());
  std::vector<std::span<const std::byte>> messages;
  std::string error;
  if (!splitOscPacket(packet, messages, error)) return count(hub_.stats.malformed);
  for (const auto& bytesOfOne : messages) {
    OscMessage message;
    if (!decodeOscMessage(bytesOfOne, message, error)) {
      count(hub_.stats.malformed);
      continue;
    }
    dispatchOsc(message, client_, hub_.catalogue, hub_.inbox, hub_.stats);
  }
}

void SocketSession::valuesChanged(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) stream_.changed(path);
  flushValues();
}

// Sends the values due, once what was queued before has gone (a client that reads slowly gets fewer,
// fresher values, never a growing queue); else comes back when they are due.
void SocketSession::flushValues() {
  if (!open_ || writing_ || !queue_.empty()) return;  // onWrite calls again when the queue drains
  for (const std::string& path : stream_.due())
    if (auto message = oscValueMessage(hub_.catalogue.scenes(), hub_.values, path))
      enqueue({std::make_shared<const std::string>(std::move(*message)), false, true});
  const auto next = stream_.next();
  if (!next || flushArmed_) return;
  flushArmed_ = true;
  flushTimer_.expires_at(*next);
  flushTimer_.async_wait([self = shared_from_this()](beast::error_code) {
    self->flushArmed_ = false;
    self->flushValues();
  });
}

void SocketSession::reply(std::string text) {
  enqueue({std::make_shared<const std::string>(std::move(text)), false});
}

void SocketSession::sendState(std::shared_ptr<const std::string> state) {
  // The front may be on the wire already; any other queued state is stale now.
  const size_t first = writing_ ? 1 : 0;
  for (size_t i = queue_.size(); i-- > first;)
    if (queue_[i].state) queue_.erase(queue_.begin() + std::ptrdiff_t(i));
  enqueue({std::move(state), true});
}

void SocketSession::enqueue(Outgoing message) {
  // A client that does not read loses replies; states replace each other, so at most two are queued.
  if (!open_ || (!message.state && !message.value && queue_.size() >= hub_.limits.maxQueuedReplies)) return;
  queue_.push_back(std::move(message));
  if (!writing_) writeNext();
}

void SocketSession::writeNext() {
  if (queue_.empty()) return;
  writing_ = true;
  socket_.binary(queue_.front().value);
  socket_.async_write(boost::asio::buffer(*queue_.front().text),
                      beast::bind_front_handler(&SocketSession::onWrite, shared_from_this()));
}

void SocketSession::onWrite(beast::error_code error, size_t) {
  writing_ = false;
  if (!queue_.empty()) queue_.pop_front();
  if (error) {
    open_ = false;
    queue_.clear();
    return;
  }
  if (queue_.empty()) flushValues();
  else writeNext();
}

}  // namespace vitrine::remote
