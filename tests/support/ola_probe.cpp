// ola_probe PORT COMMAND ...: OLA's own client library against an olad on 127.0.0.1:PORT (OLA's command
// line tools know only the default port 9010, and the tests start olad on a free one).
//   get UNIVERSE                      prints the universe's 512 values, comma-separated
//   set UNIVERSE V1,V2,...            sends one frame and prints the time it was sent (steady clock s)
//   flood UNIVERSE SECONDS            sends frames as fast as the connection takes them; prints how many
//   watch UNIVERSE SECONDS            prints every frame that comes for the universe, a line each
//                                     ("TIME V1,V2,...,V512", steady clock seconds), for SECONDS
#include <ola/Callback.h>
#include <ola/DmxBuffer.h>
#include <ola/Logging.h>
#include <ola/client/ClientArgs.h>
#include <ola/client/OlaClient.h>
#include <ola/io/SelectServer.h>
#include <ola/network/IPV4Address.h>
#include <ola/network/SocketAddress.h>
#include <ola/network/TCPSocket.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A frame's 512 values, comma-separated.
std::string valuesOf(const ola::DmxBuffer& buffer) {
  std::string values;
  for (unsigned i = 0; i < 512; ++i) values += (i ? "," : "") + std::to_string(i < buffer.Size() ? buffer.Get(i) : 0);
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: ola_probe PORT get|set|flood UNIVERSE [VALUES|SECONDS]\n");
    return 2;
  }
  ola::InitLogging(ola::OLA_LOG_WARN, ola::OLA_LOG_STDERR);
  const auto port = uint16_t(std::atoi(argv[1]));
  const std::string command = argv[2];
  const auto universe = unsigned(std::atoi(argv[3]));
  ola::io::SelectServer server;
  std::unique_ptr<ola::network::TCPSocket> socket(
      ola::network::TCPSocket::Connect(ola::network::IPV4SocketAddress(ola::network::IPV4Address::Loopback(), port)));
  if (!socket) {
    std::fprintf(stderr, "ola_probe: no olad on port %u\n", port);
    return 1;
  }
  ola::client::OlaClient client(socket.get());
  if (!client.Setup()) return 1;
  server.AddReadDescriptor(socket.get());
  int status = 0;
  if (command == "get") {
    client.FetchDMX(universe, ola::NewSingleCallback(+[](ola::io::SelectServer* ss, int* out, const ola::client::Result& result,
                                                       const ola::client::DMXMetadata&, const ola::DmxBuffer& buffer) {
      if (!result.Success()) {
        std::fprintf(stderr, "ola_probe: %s\n", result.Error().c_str());
        *out = 1;
      } else {
        std::printf("%s\n", valuesOf(buffer).c_str());
      }
      ss->Terminate();
    }, &server, &status));
    server.Run();
  } else if (command == "set" && argc >= 5) {
    ola::DmxBuffer buffer;
    buffer.SetFromString(argv[4]);
    const double sent = now();  // before the frame leaves: the latency measured from here includes the send
    client.SendDMX(universe, buffer, ola::client::SendDMXArgs(ola::NewSingleCallback(
                                         +[](ola::io::SelectServer* ss, const ola::client::Result&) { ss->Terminate(); }, &server)));
    std::printf("%.6f\n", sent);
    std::fflush(stdout);
    server.Run();  // until olad took it
  } else if (command == "flood" && argc >= 5) {
    const double until = now() + std::atof(argv[4]);
    uint64_t frames = 0;
    ola::DmxBuffer buffer;
    buffer.Blackout();
    while (now() < until) {
      for (unsigned i = 0; i < 512; ++i) buffer.SetChannel(i, uint8_t(frames + i));
      client.SendDMX(universe, buffer, ola::client::SendDMXArgs());
      ++frames;
      server.RunOnce(ola::TimeInterval(0, 0));
    }
    std::printf("%llu\n", static_cast<unsigned long long>(frames));
  } else if (command == "watch" && argc >= 5) {
    client.SetDMXCallback(ola::NewCallback(+[](const ola::client::DMXMetadata&, const ola::DmxBuffer& buffer) {
      std::printf("%.6f %s\n", now(), valuesOf(buffer).c_str());
      std::fflush(stdout);
    }));
    client.RegisterUniverse(universe, ola::client::REGISTER,
                            ola::NewSingleCallback(+[](const ola::client::Result& result) {
                              std::fprintf(stderr, "ola_probe: watching%s\n", result.Success() ? "" : (" failed: " + result.Error()).c_str());
                            }));
    server.RegisterSingleTimeout(int(std::atof(argv[4]) * 1000), ola::NewSingleCallback(&server, &ola::io::SelectServer::Terminate));
    server.Run();
  } else {
    std::fprintf(stderr, "ola_probe: unknown command %s\n", command.c_str());
    status = 2;
  }
  client.Stop();
  return status;
}
