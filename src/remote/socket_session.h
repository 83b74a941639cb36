#pragma once
// One phone's WebSocket: reads its messages (size-limited, rate-limited, parsed, checked, queued in
// the inbox), writes it state pushes and refusals through a short queue in which a newer state
// replaces an unsent older one. Or an OSCQuery client's: LISTEN and IGNORE in JSON, OSC packets in
// binary messages (checked and queued as OSC over UDP is), and the values it listens to streamed back
// as binary OSC messages at a bounded rate. Internal to the web server; Beast types inside.
#include "remote/oscquery_stream.h"
#include "remote/rate_limiter.h"
#include "remote/web_hub.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <boost/asio/steady_timer.hpp>

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace vitrine::remote {

class SocketSession : public std::enable_shared_from_this<SocketSession> {
 public:
  SocketSession(boost::beast::tcp_stream&& stream, WebHub& hub, ConnectionSlot slot, bool oscQuery = false);
  ~SocketSession();
  SocketSession(const SocketSession&) = delete;
  SocketSession& operator=(const SocketSession&) = delete;

  // Completes the upgrade that arrived as `request` (already authorised), then reads until closed.
  void accept(boost::beast::http::request<boost::beast::http::string_body> request);
  // A state push: replaces any state still waiting in the queue.
  void sendState(std::shared_ptr<const std::string> state);
  // Tells the page why its command was refused ({"type":"refused","reason":...}).
  void refuse(const std::string& reason);
  const std::string& client() const { return client_; }  // "ws ADDRESS:PORT", "oscquery ADDRESS:PORT"
  // OSCQuery: these paths' values changed (the hub's values hold the new ones); those listened to are
  // sent, coalesced to the stream's rate.
  void valuesChanged(const std::vector<std::string>& paths);

 private:
  struct Outgoing {
    std::shared_ptr<const std::string> text;
    bool state = false;
    bool value = false;  // a streamed OSC value: binary, and not held to the replies' cap
  };
  void onAccept(boost::beast::error_code error);
  void read();
  void onRead(boost::beast::error_code error, size_t bytes);
  void handle(std::string_view text);
  void handleQueryCommand(std::string_view text);
  void handleOsc(std::string_view bytes);
  void flushValues();
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
  const bool oscQuery_;
  ValueStream stream_;
  boost::asio::steady_timer flushTimer_;
  bool flushArmed_ = false;
};

}  // namespace vitrine::remote
