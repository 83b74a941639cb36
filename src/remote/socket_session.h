#pragma once
// One phone's WebSocket: reads its messages (size-limited, rate-limited, parsed, checked, queued in
// the inbox), writes it state pushes and refusals through a short queue in which a newer state
// replaces an unsent older one. Internal to the web server; Beast types inside.
#include "remote/rate_limiter.h"
#include "remote/web_hub.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <deque>
#include <memory>
#include <string>

namespace vitrine::remote {

class SocketSession : public std::enable_shared_from_this<SocketSession> {
 public:
  SocketSession(boost::beast::tcp_stream&& stream, WebHub& hub, ConnectionSlot slot);
  ~SocketSession();
  SocketSession(const SocketSession&) = delete;
  SocketSession& operator=(const SocketSession&) = delete;

  // Completes the upgrade that arrived as `request` (already authorised), then reads until closed.
  void accept(boost::beast::http::request<boost::beast::http::string_body> request);
  // A state push: replaces any state still waiting in the queue.
  void sendState(std::shared_ptr<const std::string> state);
  // Tells the page why its command was refused ({"type":"refused","reason":...}).
  void refuse(const std::string& reason);
  const std::string& client() const { return client_; }  // "ws ADDRESS:PORT"

 private:
  struct Outgoing {
    std::shared_ptr<const std::string> text;
    bool state = false;
  };
  void onAccept(boost::beast::error_code error);
  void read();
  void onRead(boost::beast::error_code error, size_t bytes);
  void handle(std::string_view text);
  void reply(std::string text);
  void enqueue(Outgoing message);
  void writeNext();
  void onWrite(boost::beast::error_code error, size_t bytes);

  boost::beast::websocket::stream<boost::beast::tcp_stream> socket_;
  WebHub& hub_;
  ConnectionSlot slot_;
  TokenBucket budget_;
  std::string client_;
  boost::beast::flat_buffer buffer_;
  std::deque<Outgoing> queue_;  // front is being written while writing_
  bool writing_ = false;
  bool open_ = false;
};

}  // namespace vitrine::remote
