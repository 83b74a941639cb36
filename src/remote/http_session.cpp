#include "remote/http_session.h"

#include "remote/access_token.h"
#include "remote/oscquery.h"
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
template <typename Request> std::string_view headerOf(const Request& request, http::field field) {
  const auto value = request[field];
  return {value.data(), value.size()};
}

// A query item that is not token=...: an OSCQuery attribute (?VALUE, ?HOST_INFO).
bool asksAnAttribute(std::string_view target) {
  const size_t question = target.find('?');
  if (question == std::string_view::npos) return false;
  for (std::string_view rest = target.substr(question + 1); !rest.empty();) {
    const size_t amp = rest.find('&');
    const std::string_view item = rest.substr(0, amp);
    if (!item.empty() && !item.starts_with("token=")) return true;
    if (amp == std::string_view::npos) break;
    rest.remove_prefix(amp + 1);
  }
  return false;
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
  // The page's socket is /socket; any other path is an OSCQuery client's (they connect to the root).
  const bool oscQuery = targetPath(targetOf(request)) != "/socket";
  if (!tokensEqual(queryValue(targetOf(request), "token"), hub_.token) && !(oscQuery && tokenlessAllowed(request))) {
    count(hub_.stats.unauthorised);
    return refuse(Status::forbidden, "Forbidden: this page needs the token printed by the gallery\n");
  }
  if (oscQuery && targetPath(targetOf(request)) != "/") return refuse(Status::not_found, "Not found\n");
  if (hub_.sockets >= hub_.limits.maxSockets) {
    count(hub_.stats.connectionsRefused);
    return refuse(Status::service_unavailable, "Too many remote controls connected\n");
  }
  auto session = std::make_shared<SocketSession>(std::move(stream_), hub_, std::move(*slot_), oscQuery);
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

  const bool token = tokensEqual(queryValue(targetOf(request), "token"), hub_.token);
  const bool oscQuery = forOscQuery(request, token);
  if (!token && !(oscQuery && tokenlessAllowed(request))) {
    count(hub_.stats.unauthorised);
    return status(Status::forbidden, "Forbidden: open the URL the gallery printed, with its token\n");
  }
  if (request.method() != http::verb::get) {
    response.set(http::field::allow, "GET");
    return status(Status::method_not_allowed, "Only GET\n");
  }
  if (oscQuery) {
    const OscQueryReply reply = answerOscQuery(hub_.catalogue.scenes(), hub_.values, hub_.host, targetOf(request));
    if (reply.status == 200) response.set(http::field::content_type, "application/json");
    if (reply.status == 400) count(hub_.stats.malformed);
    return status(Status(reply.status), reply.body);
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

bool HttpSession::forOscQuery(const Request& request, bool token) const {
  const std::string_view target = targetOf(request), path = targetPath(target);
  if (path == "/index.html" || path == "/catalogue.json" || path == "/socket") return false;
  if (path != "/") return true;
  // The root is the page for a holder of the token (a browser, the URL the gallery printed), unless
  // it asks for an attribute or for JSON alone; for a client trusted without the token, the namespace.
  if (!token || asksAnAttribute(target)) return true;
  const std::string_view accept = headerOf(request, http::field::accept);
  return accept.find("application/json") != std::string_view::npos && accept.find("text/html") == std::string_view::npos;
}

bool HttpSession::tokenlessAllowed(const Request& request) const {
  return hub_.trust && hub_.trust->allowed(address_) &&
         nativeClientRequest(request.find(http::field::origin) != request.end(), headerOf(request, http::field::host),
                             hub_.machineName);
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
