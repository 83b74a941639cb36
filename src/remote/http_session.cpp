#include "remote/http_session.h"

#include "remote/access_token.h"
#include "remote/socket_session.h"

#include <boost/beast/websocket.hpp>

namespace vitrine::remote {

namespace beast = boost::beast;
namespace http = beast::http;
using Status = http::status;

namespace {
// Beast 1.74 has its own string_view.
template <typename Request> std::string_view targetOf(const Request& request) {
  const auto target = request.target();
  return {target.data(), target.size()};
}
}  // namespace

HttpSession::HttpSession(boost::asio::ip::tcp::socket&& socket, WebHub& hub, std::string address)
    : stream_(std::move(socket)), hub_(hub), slot_(std::in_place, hub, address),
      // The buffer holds at most one whole request: headers and body within their limits.
      buffer_(hub.limits.maxRequestHeader + hub.limits.maxRequestBody), address_(std::move(address)),
      stranger_(hub.strangers.insert(hub.strangers.end(), this)) {}

HttpSession::~HttpSession() { trusted(); }

void HttpSession::trusted() {
  if (stranger_) hub_.strangers.erase(*std::exchange(stranger_, std::nullopt));
}

void HttpSession::evict() {
  trusted();
  slot_.reset();
  beast::error_code ignored;
  stream_.socket().close(ignored);  // the pending read ends with an error, and the session with it
}

void HttpSession::start() { read(); }

void HttpSession::read() {
  parser_.emplace();
  parser_->header_limit(std::uint32_t(hub_.limits.maxRequestHeader));
  parser_->body_limit(hub_.limits.maxRequestBody);
  // A stranger has a few seconds to send its request; a holder of the token, the usual time.
  stream_.expires_after(stranger_ ? hub_.limits.firstRequestTimeout : hub_.limits.requestTimeout);
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpSession::onRead, shared_from_this()));
}

void HttpSession::onRead(beast::error_code error, size_t) {
  if (error == http::error::end_of_stream) {
    beast::error_code ignored;
    stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
    return;
  }
  if (error == http::error::header_limit || error == http::error::body_limit || error == http::error::buffer_overflow) {
    count(hub_.stats.oversized);
    Response response{Status::payload_too_large, 11};
    response.set(http::field::content_type, "text/plain");
    response.body() = "Request too large\n";
    return write(std::move(response), true);
  }
  if (error) {
    // Timed out, reset, or not HTTP: bytes that parse as nothing are counted; the rest just end.
    if (error.category() == http::make_error_code(http::error::bad_target).category()) count(hub_.stats.malformed);
    return;
  }
  Request request = parser_->release();
  if (tokensEqual(queryValue(targetOf(request), "token"), hub_.token)) trusted();
  if (boost::beast::websocket::is_upgrade(request)) return upgrade(std::move(request));
  const bool close = !request.keep_alive();
  write(respond(request), close);
}

void HttpSession::upgrade(Request request) {
  const auto refuse = [&](Status status, std::string_view body) {
    Response response{status, request.version()};
    response.set(http::field::content_type, "text/plain");
    response.body() = std::string(body);
    write(std::move(response), true);
  };
  if (!tokensEqual(queryValue(targetOf(request), "token"), hub_.token)) {
    count(hub_.stats.unauthorised);
    return refuse(Status::forbidden, "Forbidden: this page needs the token printed by the gallery\n");
  }
  if (targetPath(targetOf(request)) != "/socket") return refuse(Status::not_found, "Not found\n");
  if (hub_.sockets >= hub_.limits.maxSockets) {
    count(hub_.stats.connectionsRefused);
    return refuse(Status::service_unavailable, "Too many remote controls connected\n");
  }
  auto session = std::make_shared<SocketSession>(std::move(stream_), hub_, std::move(*slot_));
  slot_.reset();
  session->accept(std::move(request));
}

HttpSession::Response HttpSession::respond(const Request& request) {
  Response response{Status::ok, request.version()};
  response.set(http::field::server, "vitrine");
  response.set(http::field::cache_control, "no-store");
  response.set(http::field::content_type, "text/plain; charset=utf-8");
  response.set("X-Content-Type-Options", "nosniff");
  response.set("Referrer-Policy", "no-referrer");  // the token is in the URL
  response.keep_alive(request.keep_alive());
  const auto status = [&](Status code, std::string_view body) {
    response.result(code);
    response.body() = std::string(body);
    return response;
  };

  if (!tokensEqual(queryValue(targetOf(request), "token"), hub_.token)) {
    count(hub_.stats.unauthorised);
    return status(Status::forbidden, "Forbidden: open the URL the gallery printed, with its token\n");
  }
  if (request.method() != http::verb::get) {
    response.set(http::field::allow, "GET");
    return status(Status::method_not_allowed, "Only GET\n");
  }
  const std::string_view path = targetPath(targetOf(request));
  if (path == "/" || path == "/index.html") {
    response.set(http::field::content_type, "text/html; charset=utf-8");
    // Nothing but the page itself and its socket: no external resources, no frames.
    response.set("Content-Security-Policy",
                 "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                 "connect-src 'self'; img-src data:; frame-ancestors 'none'; base-uri 'none'; form-action 'none'");
    return status(Status::ok, hub_.page);
  }
  if (path == "/catalogue.json") {
    response.set(http::field::content_type, "application/json");
    return status(Status::ok, hub_.catalogue.json());
  }
  return status(Status::not_found, "Not found\n");
}

void HttpSession::write(Response response, bool close) {
  response.keep_alive(!close);
  response.prepare_payload();
  response_ = std::make_shared<Response>(std::move(response));
  http::async_write(stream_, *response_,
                    beast::bind_front_handler(&HttpSession::onWrite, shared_from_this(), close));
}

void HttpSession::onWrite(bool close, beast::error_code error, size_t) {
  response_.reset();
  if (error) return;
  if (close) {
    beast::error_code ignored;
    stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
    return;
  }
  read();
}

}  // namespace vitrine::remote
