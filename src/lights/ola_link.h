#pragma once
// The lights thread's connection to olad, the Open Lighting Architecture's daemon (which speaks Art-Net,
// sACN and USB interfaces to the wire): DMX frames out, the frames of listened universes in. The only
// file that includes OLA's headers. Used from one thread, which calls pump() to let OLA run.
#include "lights/fixtures.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vitrine::lights {

class OlaLink {
 public:
  // Called from pump() for each frame received on a listened universe: its universe and channels.
  using Received = std::function<void(uint32_t universe, const uint8_t* channels, size_t count)>;

  OlaLink(uint16_t port, Received received);
  ~OlaLink();
  OlaLink(const OlaLink&) = delete;
  OlaLink& operator=(const OlaLink&) = delete;

  // Tries to connect once (to 127.0.0.1:port, at once refused when olad is not there); "" on success,
  // else why not.
  std::string connect();
  bool connected() const;
  // Register for the frames of these universes (and forget the others listened to before).
  void listen(const std::vector<uint32_t>& universes);
  void send(uint32_t universe, const Universe& channels);
  // Frames sent on this connection, and those olad has answered for (it has taken them).
  uint64_t sent() const;
  uint64_t acknowledged() const;
  // Lets OLA read and write for at most `seconds`; false when the connection closed meanwhile.
  bool pump(double seconds);
  void disconnect();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vitrine::lights
