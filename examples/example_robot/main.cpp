// example_robot: the smallest robot program on the installed client library. Registers
// with its own account (SPEC 5: Ready, answered by Start then SetMap), decodes the map it
// is sent and prints what it holds. RobotClient::ready() does the same in one call; the
// steps are spelled out here to show the wire.
//
// Connection settings as for every fleetmap program (protocol/db_settings.h): the config
// file (--config, else FLEETMAP_CONFIG, ...), FLEETMAP_* variables, then the flags.
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "client/robot_client.h"
#include "protocol/map_codec.h"

namespace {

constexpr const char* kUsage =
    "usage: example_robot [--config FILE] [--user NAME] [--password-file FILE] [--timeout S]\n"
    "Sends Ready as robot NAME, waits up to S seconds (default 10) for the server's SetMap\n"
    "and prints it. Exit codes: 0 ok, 1 no answer or refused, 64 usage.\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  std::optional<std::string> config, user, password_file;
  int timeout_s = 10;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (i + 1 == argc || std::strncmp(argv[i + 1], "--", 2) == 0) {
      std::cerr << "example_robot: " << arg << ": expected a value\n" << kUsage;
      return 64;
    }
    const std::string value = argv[++i];
    if (arg == "--config") config = value;
    else if (arg == "--user") user = value;
    else if (arg == "--password-file") password_file = value;
    else if (arg == "--timeout") timeout_s = std::atoi(value.c_str());
    else {
      std::cerr << "example_robot: unknown option " << arg << "\n" << kUsage;
      return 64;
    }
  }
  if (timeout_s <= 0) {
    std::cerr << "example_robot: --timeout: expected whole seconds > 0\n";
    return 64;
  }
  try {
    DbSettings s = load_settings(Role::Robot, config);
    if (user) s.user = *user;
    if (password_file) {
      std::ifstream in(*password_file);
      if (!std::getline(in, s.password)) throw std::runtime_error(*password_file + ": expected the password on line 1");
    }
    s.socket.clear();  // robots connect over the network, as real ones do
    RobotClient client(s, std::chrono::seconds(timeout_s));
    const long long magic = getpid();
    const auto ready = client.send(RequestOp::Ready, Json{{"magic", magic}, {"encoding", "seed"}});
    const std::chrono::milliseconds timeout = std::chrono::seconds(timeout_s);
    const ReceivedAnswer start = client.await(ready, 1, timeout).at(0);
    if (start.op != "Start") throw RobotClientError("Ready answered by " + start.op + " " + start.params.dump());
    const StartParams sp = decode_start(start.params);
    const ReceivedAnswer set_map = client.await(ready, 1, timeout).at(0);
    if (set_map.op != "SetMap") throw RobotClientError("expected SetMap after Start, got " + set_map.op);
    const SetMapParams mp = decode_set_map(set_map.params);
    const Map map = decode_map(set_map.payload.value_or(""), mp.encoding, MapKind::Window);
    if (map.segment_count() != mp.segments)
      throw RobotClientError("SetMap announces " + std::to_string(mp.segments) + " segments, payload holds " +
                             std::to_string(map.segment_count()));
    std::cout << "Start: robot " << sp.robot_id << " (" << s.user << "), Alive every " << sp.alive_period_s << " s\n"
              << "SetMap: " << map.obstacles.size() << " obstacles, " << map.segment_count() << " segments, border ("
              << mp.border[0] << ", " << mp.border[1] << ")-(" << mp.border[2] << ", " << mp.border[3] << ")\n";
    return 0;
  } catch (const std::exception& e) {  // RobotClientError (time-out, refused), DbError, bad config
    std::cerr << "example_robot: " << e.what() << "\n";
    return 1;
  }
}
