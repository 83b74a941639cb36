#include "remote/mdns_announcer.h"

#include <avahi-client/client.h>
#include <avahi-client/publish.h>
#include <avahi-common/alternative.h>
#include <avahi-common/error.h>
#include <avahi-common/malloc.h>
#include <avahi-common/thread-watch.h>
#include <avahi-common/timeval.h>
#include <fmt/format.h>

#include <atomic>
#include <utility>

namespace vitrine::remote {

struct MdnsAnnouncer::Impl {
  std::string name;
  const uint16_t port;
  const int interfaceIndex;
  const Say say;
  std::atomic<State> state{State::Connecting};
  bool toldNoDaemon = false;  // Avahi's thread only, like everything below
  AvahiThreadedPoll* poll = nullptr;
  AvahiClient* client = nullptr;
  AvahiEntryGroup* group = nullptr;
  AvahiTimeout* retry = nullptr;  // without a system bus, nothing says when a daemon appears: ask again

  Impl(std::string serviceName, uint16_t servicePort, int interface, Say sayLine)
      : name(std::move(serviceName)), port(servicePort), interfaceIndex(interface), say(std::move(sayLine)) {}

  void tell(const std::string& line) {
    if (say) say(line);
  }

  void fail(const std::string& why) {
    state = State::Failed;
    tell("mDNS: " + why + "; OSCQuery clients must be given the address");
  }

  void noDaemon() {
    state = State::NoDaemon;
    if (!std::exchange(toldNoDaemon, true))
      tell("mDNS: no Avahi daemon runs (avahi-daemon); OSCQuery is not announced, and will be if one starts");
  }

  // A client that waits for a daemon rather than failing without one (AVAHI_CLIENT_NO_FAIL). With no
  // system bus at all it cannot even wait: it is tried again every few seconds.
  void connect() {
    int error = 0;
    client = avahi_client_new(avahi_threaded_poll_get(poll), AVAHI_CLIENT_NO_FAIL, &Impl::onClient, this, &error);
    if (client) return;
    if (error != AVAHI_ERR_NO_DAEMON) return fail(fmt::format("cannot start Avahi's client ({})", avahi_strerror(error)));
    noDaemon();
    const AvahiPoll* api = avahi_threaded_poll_get(poll);
    timeval when{};
    avahi_elapse_time(&when, kRetryMs, 0);
    if (retry) api->timeout_update(retry, &when);
    else retry = api->timeout_new(api, &when, [](AvahiTimeout*, void* data) { static_cast<Impl*>(data)->connect(); }, this);
  }
  static constexpr unsigned kRetryMs = 5000;

  void addServices() {
    if (!group) group = avahi_entry_group_new(client, &Impl::onGroup, this);
    if (!group) return fail(fmt::format("cannot make an entry group ({})", avahi_strerror(avahi_client_errno(client))));
    if (!avahi_entry_group_is_empty(group)) return;
    const AvahiIfIndex interface = interfaceIndex < 0 ? AVAHI_IF_UNSPEC : AvahiIfIndex(interfaceIndex);
    for (const char* type : {"_oscjson._tcp", "_osc._udp"}) {
      const int error = avahi_entry_group_add_service(group, interface, AVAHI_PROTO_UNSPEC, AvahiPublishFlags(0),
                                                      name.c_str(), type, nullptr, nullptr, port, nullptr);
      if (error == AVAHI_ERR_COLLISION) return rename();
      if (error < 0) return fail(fmt::format("cannot add {} ({})", type, avahi_strerror(error)));
    }
    if (const int error = avahi_entry_group_commit(group); error < 0)
      fail(fmt::format("cannot announce ({})", avahi_strerror(error)));
  }

  // Another service on the network has the name: take Avahi's next ("Vitrine on studio #2").
  void rename() {
    char* next = avahi_alternative_service_name(name.c_str());
    name = next;
    avahi_free(next);
    if (group) avahi_entry_group_reset(group);
    addServices();
  }

  static void onGroup(AvahiEntryGroup* group, AvahiEntryGroupState groupState, void* data) {
    auto& self = *static_cast<Impl*>(data);
    self.group = group;
    switch (groupState) {
      case AVAHI_ENTRY_GROUP_ESTABLISHED:
        self.state = State::Announced;
        self.tell(fmt::format("mDNS: announced as \"{}\" (_oscjson._tcp, _osc._udp, port {})", self.name, self.port));
        break;
      case AVAHI_ENTRY_GROUP_COLLISION: self.rename(); break;
      case AVAHI_ENTRY_GROUP_FAILURE:
        self.fail(fmt::format("the announcement failed ({})",
                              avahi_strerror(avahi_client_errno(avahi_entry_group_get_client(group)))));
        break;
      case AVAHI_ENTRY_GROUP_UNCOMMITED:
      case AVAHI_ENTRY_GROUP_REGISTERING: break;
    }
  }

  static void onClient(AvahiClient* client, AvahiClientState clientState, void* data) {
    auto& self = *static_cast<Impl*>(data);
    self.client = client;  // the callback can run inside avahi_client_new, before it returns
    switch (clientState) {
      case AVAHI_CLIENT_S_RUNNING: self.addServices(); break;
      case AVAHI_CLIENT_S_COLLISION:
      case AVAHI_CLIENT_S_REGISTERING:  // the host's own name changed: announce again once it settles
        if (self.group) avahi_entry_group_reset(self.group);
        break;
      case AVAHI_CLIENT_CONNECTING: self.noDaemon(); break;
      case AVAHI_CLIENT_FAILURE:
        if (avahi_client_errno(client) == AVAHI_ERR_DISCONNECTED) {  // the daemon went away: wait for it again
          self.group = nullptr;  // freed with its client
          avahi_client_free(client);
          self.client = nullptr;
          self.state = State::Connecting;
          self.connect();
        } else {
          self.fail(fmt::format("Avahi's client failed ({})", avahi_strerror(avahi_client_errno(client))));
        }
        break;
    }
  }
};

MdnsAnnouncer::MdnsAnnouncer(std::string name, uint16_t port, int interfaceIndex, Say say)
    : impl_(std::make_unique<Impl>(std::move(name), port, interfaceIndex, std::move(say))) {
  impl_->poll = avahi_threaded_poll_new();
  if (!impl_->poll) {
    impl_->fail("cannot start Avahi's thread");
    return;
  }
  impl_->connect();  // before the thread starts: its first callbacks run here, on this thread
  if (avahi_threaded_poll_start(impl_->poll) < 0) impl_->fail("cannot start Avahi's thread");
}

MdnsAnnouncer::~MdnsAnnouncer() {
  if (!impl_->poll) return;
  avahi_threaded_poll_stop(impl_->poll);  // joins the thread: nothing below races a callback
  if (impl_->client) avahi_client_free(impl_->client);  // frees the group too, withdrawing the services
  avahi_threaded_poll_free(impl_->poll);
}

MdnsAnnouncer::State MdnsAnnouncer::state() const { return impl_->state.load(); }

}  // namespace vitrine::remote
