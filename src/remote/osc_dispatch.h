#pragma once
// One decoded OSC message from a client that may send it: turned into a command, checked against the
// catalogue and queued in the inbox, or counted where it fails. The same for OSC over UDP and OSC
// sent over an OSCQuery WebSocket, so both paths accept and refuse exactly the same messages.
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/osc_packet.h"
#include "remote/stats.h"

#include <string>

namespace vitrine::remote {

// `client` names the sender for logs and refusals ("osc 192.168.1.20"). A refusal by the check is
// handed to the inbox for the console: OSC has no reply channel.
void dispatchOsc(const OscMessage& message, const std::string& client, const Catalogue& catalogue, RemoteInbox& inbox,
                 RemoteStats& stats);

}  // namespace vitrine::remote
