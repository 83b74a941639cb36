#pragma once
// The remote control announced over mDNS (DNS-SD) through the Avahi daemon, so OSCQuery clients find
// it with no address typed: "_oscjson._tcp" (the OSCQuery namespace over HTTP, and its WebSocket) and
// "_osc._udp" (OSC itself), both on the remote control's port. Avahi's client runs on its own thread
// (its threaded poll); nothing here waits on the daemon, so the frame loop never does. Where no daemon
// runs, `say` gets one line and the rest runs; a daemon that starts or restarts later is followed, and
// the services are announced then. Avahi's headers stay inside the .cpp: the only file that has them.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace vitrine::remote {

class MdnsAnnouncer {
 public:
  using Say = std::function<void(const std::string& line)>;  // called on Avahi's thread
  enum class State { Connecting, NoDaemon, Announced, Failed };

  // `name`: the service's instance name ("Vitrine on studio"); Avahi picks "... #2" on a clash.
  // `interfaceIndex`: the network interface to announce on (a bind to one address), or -1 for all.
  MdnsAnnouncer(std::string name, uint16_t port, int interfaceIndex, Say say);
  ~MdnsAnnouncer();  // withdraws the services and joins Avahi's thread
  MdnsAnnouncer(const MdnsAnnouncer&) = delete;
  MdnsAnnouncer& operator=(const MdnsAnnouncer&) = delete;

  State state() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace vitrine::remote
