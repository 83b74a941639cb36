#pragma once
// Shared by the web server's tests: an HTTP request on loopback and its response, its reads limited
// (remote_test_support.h) so a server that never answers fails the test instead of hanging it.
#include "remote_test_support.h"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vitrine::remote::testing {

using Headers = std::vector<std::pair<std::string, std::string>>;

// One request on an open connection, and its response.
template <typename Body>
boost::beast::http::response<boost::beast::http::string_body> roundTrip(boost::asio::ip::tcp::socket& socket,
                                                                       const boost::beast::http::request<Body>& request) {
  boost::beast::http::write(socket, request);
  boost::beast::flat_buffer buffer;
  boost::beast::http::response<boost::beast::http::string_body> response;
  boost::beast::http::read(socket, buffer, response);
  return response;
}

// One request on a connection of its own to 127.0.0.1:`port`, with Host 127.0.0.1 unless `headers`
// names another; `headers` are set in order (a name given again replaces the earlier value).
inline boost::beast::http::response<boost::beast::http::string_body> request(
    uint16_t port, const std::string& target, boost::beast::http::verb verb = boost::beast::http::verb::get,
    const Headers& headers = {}) {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket socket(io);
  socket.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  limitReads(socket);
  boost::beast::http::request<boost::beast::http::string_body> request{verb, target, 11};
  request.set(boost::beast::http::field::host, "127.0.0.1");
  for (const auto& [name, value] : headers) request.set(name, value);
  return roundTrip(socket, request);
}

// The HTTP status a WebSocket upgrade request for `target` gets: 101 when the socket would open, else
// why not; `extra` headers are added to the upgrade's.
inline unsigned upgradeStatus(uint16_t port, const std::string& target, const Headers& extra = {}) {
  Headers headers{{"Upgrade", "websocket"},
                  {"Connection", "Upgrade"},
                  {"Sec-WebSocket-Key", "dGhlIHNhbXBsZSBub25jZQ=="},
                  {"Sec-WebSocket-Version", "13"}};
  headers.insert(headers.end(), extra.begin(), extra.end());
  return request(port, target, boost::beast::http::verb::get, headers).result_int();
}

}  // namespace vitrine::remote::testing
