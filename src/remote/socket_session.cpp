#include "remote/socket_session.h"

#include "remote/messages.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace vitrine::remote {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

SocketSession::SocketSession(beast::tcp_stream&& stream, WebHub& hub, ConnectionSlot slot)
    : socket_(std::move(stream)), hub_(hub), slot_(std::move(slot)), budget_(hub.limits.perSocket) {
  ++hub_.sockets;
  beast::error_code ignored;
  const auto peer = beast::get_lowest_layer(socket_).socket().remote_endpoint(ignored);
  client_ = fmt::format("ws {}:{}", peer.address().to_string(ignored), peer.port());
}

SocketSession::~SocketSession() {
  hub_.openSockets.erase(this);
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
  hub_.openSockets.insert(this);
  if (hub_.lastState) sendState(hub_.lastState);
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
  if (!budget_.take()) {
    count(hub_.stats.rateLimited);
  } else if (!socket_.got_text()) {
    count(hub_.stats.malformed);
    reply(R"({"type":"refused","reason":"send text messages of JSON"})");
  } else {
    const auto data = buffer_.cdata();
    handle(std::string_view(static_cast<const char*>(data.data()), data.size()));
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
  if (!open_ || (!message.state && queue_.size() >= hub_.limits.maxQueuedReplies)) return;
  queue_.push_back(std::move(message));
  if (!writing_) writeNext();
}

void SocketSession::writeNext() {
  if (queue_.empty()) return;
  writing_ = true;
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
  writeNext();
}

}  // namespace vitrine::remote
