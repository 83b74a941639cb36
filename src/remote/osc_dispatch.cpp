#include "remote/osc_dispatch.h"

#include "remote/messages.h"

namespace vitrine::remote {

void dispatchOsc(const OscMessage& message, const std::string& client, const Catalogue& catalogue, RemoteInbox& inbox,
                 RemoteStats& stats) {
  if (message.path == "/vitrine/token") return count(stats.accepted);  // harmless from a trusted sender
  ParseResult parsed = commandFromOsc(message.path, message.args, catalogue);
  if (!parsed.command) return count(stats.malformed);
  if (std::string why = catalogue.check(*parsed.command); !why.empty()) {
    count(stats.refused);
    inbox.refused({client, std::move(why)});
    return;
  }
  parsed.command->client = client;
  if (inbox.push(std::move(*parsed.command))) count(stats.accepted);
  else count(stats.dropped);
}

}  // namespace vitrine::remote
