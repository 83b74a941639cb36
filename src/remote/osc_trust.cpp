#include "remote/osc_trust.h"

#include "remote/access_token.h"

#include <algorithm>
#include <cctype>

namespace vitrine::remote {

bool OscTrust::allowed(std::string_view address) const {
  if (access_.open) return true;
  for (const Network& network : access_.allow)
    if (contains(network, address)) return true;
  const std::lock_guard lock(mutex_);
  return std::find(trusted_.begin(), trusted_.end(), address) != trusted_.end();
}

bool OscTrust::offer(std::string_view address, std::string_view token) {
  if (access_.token.empty() || !tokensEqual(token, access_.token)) return false;
  const std::lock_guard lock(mutex_);
  if (std::find(trusted_.begin(), trusted_.end(), address) != trusted_.end()) return true;
  if (trusted_.size() >= access_.maxTrusted) trusted_.erase(trusted_.begin());
  trusted_.emplace_back(address);
  return true;
}

namespace {

bool equalNoCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool allOf(std::string_view text, bool (*good)(char)) { return !text.empty() && std::all_of(text.begin(), text.end(), good); }

}  // namespace

bool nativeClientRequest(bool hasOrigin, std::string_view host, std::string_view machineName) {
  if (hasOrigin || host.empty()) return false;
  if (host.front() == '[') {  // an IPv6 literal, then perhaps ":port"
    const size_t close = host.find(']');
    if (close == std::string_view::npos) return false;
    const std::string_view rest = host.substr(close + 1);
    return allOf(host.substr(1, close - 1), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) || c == ':' || c == '.'; }) &&
           (rest.empty() || (rest.front() == ':' && allOf(rest.substr(1), [](char c) { return c >= '0' && c <= '9'; })));
  }
  const size_t colon = host.rfind(':');
  if (colon != std::string_view::npos) {
    if (!allOf(host.substr(colon + 1), [](char c) { return c >= '0' && c <= '9'; })) return false;
    host = host.substr(0, colon);
  }
  if (allOf(host, [](char c) { return (c >= '0' && c <= '9') || c == '.'; })) return true;  // IPv4
  if (equalNoCase(host, "localhost")) return true;
  if (machineName.empty()) return false;
  if (host.size() > 6 && equalNoCase(host.substr(host.size() - 6), ".local")) host.remove_suffix(6);
  return equalNoCase(host, machineName);
}

}  // namespace vitrine::remote
