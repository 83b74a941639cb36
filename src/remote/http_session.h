#pragma once
// One TCP connection's HTTP requests: the page, the catalogue, or the upgrade to a WebSocket, each
// only with the right token. Internal to the web server; Beast types inside.
#include "remote/web_hub.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <memory>
#include <optional>

namespace vitrine::remote {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket&& socket, WebHub& hub, std::string address);
  ~HttpSession();
  void start();
  const std::string& address() const { return address_; }
  // Closes a connection that has not shown the token, to make room for a new one: it leaves the
  // hub's strangers and gives its slot back now, before its pending read ends.
  void evict();

 private:
  using Request = boost::beast::http::request<boost::beast::http::string_body>;
  using Response = boost::beast::http::response<boost::beast::http::string_body>;

  void read();
  void onRead(boost::beast::error_code error, size_t bytes);
  void upgrade(Request request);
  Response respond(const Request& request);
  void write(Response response, bool close);
  void onWrite(bool close, boost::beast::error_code error, size_t bytes);
  void trusted();  // it sent the token: no longer a stranger
  // Whether the request is for the OSCQuery namespace (every path but the page's own), and whether it
  // may have it without the token (OSC's network rule, from a native client).
  bool forOscQuery(const Request& request, bool token) const;
  bool tokenlessAllowed(const Request& request) const;

  boost::beast::tcp_stream stream_;
  WebHub& hub_;
  std::optional<ConnectionSlot> slot_;  // handed to the socket session on upgrade
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<Response> response_;  // alive until written
  std::string address_;
  std::optional<std::list<HttpSession*>::iterator> stranger_;  // in hub_.strangers until trusted
};

}  // namespace vitrine::remote
