// A Link peer for the tests (tests/cli/link_session.sh), built with the same library as Vitrine. It
// joins the session and prints what it sees as lines on stdout, flushed at once:
//
//   sample HOST_US BEAT BPM PEERS PLAYING   every 20 ms: the timeline (beats at quantum 4)
//   tempo-seen HOST_US BPM                  the session's tempo changed (another peer set it)
//   tempo-set HOST_US BPM                   this peer set it (a command below)
//
// and takes commands on stdin, one a line: "tempo BPM", "play 1|0", "flood RATE SECONDS" (that many
// tempo changes a second, alternating 100 and 140 BPM, for that long), "quit". Host times are Link's
// clock (CLOCK_MONOTONIC_RAW in microseconds), the same in every process of the machine.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <ableton/Link.hpp>
#pragma GCC diagnostic pop

#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

constexpr double kQuantum = 4.0;

long long micros(const ableton::Link& link) { return (long long)link.clock().micros().count(); }

void setTempo(ableton::Link& link, double bpm) {
  auto state = link.captureAppSessionState();
  state.setTempo(bpm, link.clock().micros());
  link.commitAppSessionState(state);
}

}  // namespace

int main(int argc, char** argv) {
  const double startBpm = argc > 1 ? std::atof(argv[1]) : 120.0;
  ableton::Link link(startBpm);
  link.enableStartStopSync(true);
  link.enable(true);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::string pending;
  double seenBpm = link.captureAppSessionState().tempo();
  long long nextSample = 0, floodUntil = 0, nextFlood = 0, floodEvery = 0;
  bool floodHigh = false, open = true;
  for (;;) {
    pollfd in{STDIN_FILENO, POLLIN, 0};
    if (open && poll(&in, 1, 1) > 0) {
      char buffer[256];
      const ssize_t got = read(STDIN_FILENO, buffer, sizeof buffer);
      if (got <= 0) open = false;  // stdin closed: run on until killed
      else pending.append(buffer, size_t(got));
    } else if (!open) {
      usleep(1000);
    }
    for (size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
      std::istringstream line(pending.substr(0, end));
      std::string command;
      line >> command;
      if (command == "quit") return 0;
      if (command == "tempo") {
        double bpm = 0.0;
        line >> bpm;
        setTempo(link, bpm);
        seenBpm = link.captureAppSessionState().tempo();
        std::printf("tempo-set %lld %.6f\n", micros(link), seenBpm);
      } else if (command == "play") {
        int on = 0;
        line >> on;
        auto state = link.captureAppSessionState();
        state.setIsPlaying(on != 0, link.clock().micros());
        link.commitAppSessionState(state);
      } else if (command == "flood") {
        double rate = 0.0, seconds = 0.0;
        line >> rate >> seconds;
        floodEvery = rate > 0.0 ? (long long)(1e6 / rate) : 0;
        nextFlood = micros(link);
        floodUntil = floodEvery > 0 ? nextFlood + (long long)(seconds * 1e6) : 0;
        std::printf("flood %lld %.1f %.1f\n", nextFlood, rate, seconds);
      }
    }
    const long long now = micros(link);
    if (floodUntil > 0 && now >= nextFlood) {
      if (now >= floodUntil) {
        floodUntil = 0;
        std::printf("flood-end %lld\n", now);
      } else {
        setTempo(link, (floodHigh = !floodHigh) ? 140.0 : 100.0);
        seenBpm = link.captureAppSessionState().tempo();
        nextFlood += floodEvery;
      }
    }
    const auto state = link.captureAppSessionState();
    if (state.tempo() != seenBpm) {
      seenBpm = state.tempo();
      std::printf("tempo-seen %lld %.6f\n", now, seenBpm);
    }
    if (now >= nextSample) {
      nextSample = now + 20'000;
      const auto at = std::chrono::microseconds(now);
      std::printf("sample %lld %.6f %.6f %zu %d\n", now, state.beatAtTime(at, kQuantum), state.tempo(), link.numPeers(),
                  state.isPlaying() ? 1 : 0);
    }
  }
}
