#include "live/midi_input.h"

#include "core/printable.h"

#include <RtMidi.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <utility>

namespace vitrine::live {
namespace {

// The ALSA client name of each RtMidiIn we make; ports of clients of this name are ours, never opened.
constexpr char kClientName[] = "Vitrine";

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

struct MidiInput::Impl {
  // Declared before the ports, so destroyed after them: RtMidi's threads reach these until a port closes.
  std::mutex queueMutex;
  std::vector<MidiMessage> queue;
  std::vector<TimedByte> system;  // under queueMutex too
  std::mutex errorMutex;
  std::string lastError;  // RtMidi's last complaint, the reason when an open fails

  double rescanSeconds = 1.0;
  double lastScan = 0.0;
  std::string reason;  // why there is no MIDI; empty while active

  struct Port {
    std::string name;
    std::unique_ptr<RtMidiIn> in;
  };
  std::unique_ptr<RtMidiIn> probe;  // lists the ports, opens none
  std::vector<Port> open;           // in the order they were connected
  std::vector<std::string> failed;  // would not open: not tried again until they go and come back

  std::string start();
  std::unique_ptr<RtMidiIn> makeClient();
  void scan();
  void connect(const std::string& name);
  std::string takeError();

  // On RtMidi's input thread: keeps complete channel voice messages, and system messages' bytes for
  // the clocks; drops the rest.
  static void onMessage(double, std::vector<unsigned char>* bytes, void* user) {
    if (!bytes || bytes->empty()) return;
    const uint8_t status = (*bytes)[0];
    if (status >= 0xF0) {
      if (bytes->size() > kMaxSystemMessage) return;
      const double now = steadySeconds();
      auto* self = static_cast<Impl*>(user);
      const std::lock_guard lock(self->queueMutex);
      if (self->system.size() + bytes->size() > kQueueLimit) return;
      for (const unsigned char byte : *bytes) self->system.push_back({now, byte});
      return;
    }
    const int data = midiDataBytes(status);
    if (data == 0 || bytes->size() < size_t(1 + data)) return;
    const MidiMessage message{steadySeconds(), status, (*bytes)[1], data == 2 ? (*bytes)[2] : uint8_t(0)};
    auto* self = static_cast<Impl*>(user);
    const std::lock_guard lock(self->queueMutex);
    if (self->queue.size() < kQueueLimit) self->queue.push_back(message);
  }

  // With no error callback RtMidi prints warnings to stderr and throws errors, also on its own thread,
  // which would end the program; here warnings are dropped and an error kept as the reason it gives.
  static void onError(RtMidiError::Type type, const std::string& text, void* user) {
    if (type == RtMidiError::WARNING || type == RtMidiError::DEBUG_WARNING) return;
    auto* self = static_cast<Impl*>(user);
    const std::lock_guard lock(self->errorMutex);
    self->lastError = trimmed(text);
  }
};

std::string MidiInput::Impl::start() {
  std::vector<RtMidi::Api> apis;
  RtMidi::getCompiledApi(apis);
  if (std::find(apis.begin(), apis.end(), RtMidi::LINUX_ALSA) == apis.end()) return "RtMidi was built without ALSA";
  // Checked first because alsa-lib prints its own complaint when the open fails.
  if (::access("/dev/snd/seq", R_OK | W_OK) != 0)
    return errno == ENOENT ? "no ALSA sequencer, /dev/snd/seq is missing"
                           : fmt::format("/dev/snd/seq: {}", std::strerror(errno));
  try {
    probe = makeClient();
  } catch (const RtMidiError& e) {
    return trimmed(e.getMessage());
  } catch (const std::exception& e) {
    return trimmed(e.what());
  }
  scan();
  return {};
}

// Throws RtMidiError when the sequencer cannot be opened: the callback can only be set afterwards.
std::unique_ptr<RtMidiIn> MidiInput::Impl::makeClient() {
  auto client = std::make_unique<RtMidiIn>(RtMidi::LINUX_ALSA, kClientName);
  client->setErrorCallback(&onError, this);
  return client;
}

std::string MidiInput::Impl::takeError() {
  const std::lock_guard lock(errorMutex);
  return std::exchange(lastError, {});
}

void MidiInput::Impl::scan() {
  lastScan = steadySeconds();
  std::vector<std::string> present;
  const unsigned count = probe->getPortCount();
  for (unsigned i = 0; i < count; ++i) {
    std::string name = probe->getPortName(i);
    if (!name.empty() && !name.starts_with(std::string(kClientName) + ":")) present.push_back(std::move(name));
  }
  std::erase_if(open, [&](const Port& port) {
    if (contains(present, port.name)) return false;
    std::fprintf(stderr, "vitrine: MIDI in: %s disconnected\n", port.name.c_str());
    return true;  // erasing destroys the RtMidiIn, which closes the port and joins its thread
  });
  std::erase_if(failed, [&](const std::string& name) { return !contains(present, name); });
  for (const std::string& name : present) {
    const bool known = contains(failed, name) ||
                       std::any_of(open.begin(), open.end(), [&](const Port& port) { return port.name == name; });
    if (!known) connect(name);
  }
}

void MidiInput::Impl::connect(const std::string& name) {
  takeError();
  std::unique_ptr<RtMidiIn> client;
  try {
    client = makeClient();
  } catch (const RtMidiError& e) {
    failed.push_back(name);
    std::fprintf(stderr, "vitrine: MIDI in: %s could not be opened (%s)\n", name.c_str(),
                 trimmed(e.getMessage()).c_str());
    return;
  }
  // Port numbers belong to each client's own listing, which may have changed since the probe's.
  const unsigned count = client->getPortCount();
  unsigned index = 0;
  while (index < count && client->getPortName(index) != name) ++index;
  if (index == count) return;  // gone already; the next scan will say nothing about it
  // Timing messages (clock, MIDI timecode) and SysEx (MTC's full frames) are the show's clocks.
  client->ignoreTypes(/*midiSysex=*/false, /*midiTime=*/false, /*midiSense=*/true);
  client->setCallback(&onMessage, this);
  client->openPort(index, "Vitrine in");
  if (!client->isPortOpen()) {
    failed.push_back(name);
    const std::string why = takeError();
    std::fprintf(stderr, "vitrine: MIDI in: %s could not be opened (%s)\n", name.c_str(),
                 why.empty() ? "no reason given" : why.c_str());
    return;
  }
  open.push_back({name, std::move(client)});
  std::fprintf(stderr, "vitrine: MIDI in: %s connected\n", name.c_str());
}

MidiInput::MidiInput() : MidiInput(Options{}) {}

MidiInput::MidiInput(Options options) : impl_(std::make_unique<Impl>()) {
  impl_->rescanSeconds = options.rescanSeconds;
  impl_->reason = options.useDevices ? impl_->start() : "not asked to use devices";
  if (!impl_->reason.empty()) {
    impl_->probe.reset();
    std::fprintf(stderr, "vitrine: no MIDI input (%s): MIDI off\n", impl_->reason.c_str());
  }
}

MidiInput::~MidiInput() = default;

double MidiInput::clockSeconds() { return steadySeconds(); }

void MidiInput::poll() {
  if (!impl_->probe) return;
  if (steadySeconds() - impl_->lastScan < impl_->rescanSeconds) return;
  impl_->scan();
}

std::vector<MidiMessage> MidiInput::drain() {
  std::vector<MidiMessage> messages;
  const std::lock_guard lock(impl_->queueMutex);
  messages.swap(impl_->queue);
  return messages;
}

std::vector<MidiInput::TimedByte> MidiInput::drainSystem() {
  std::vector<TimedByte> bytes;
  const std::lock_guard lock(impl_->queueMutex);
  bytes.swap(impl_->system);
  return bytes;
}

std::vector<std::string> MidiInput::ports() const {
  std::vector<std::string> names;
  for (const Impl::Port& port : impl_->open) names.push_back(port.name);
  return names;
}

bool MidiInput::active() const { return impl_->reason.empty(); }

std::string MidiInput::status() const {
  if (!active()) return fmt::format("no MIDI ({})", impl_->reason);
  const std::vector<std::string> names = ports();
  std::string text = fmt::format("MIDI in: {} port{}", names.size(), names.size() == 1 ? "" : "s");
  if (!names.empty()) text += fmt::format(" ({})", fmt::join(names, ", "));
  return text;
}

}  // namespace vitrine::live
