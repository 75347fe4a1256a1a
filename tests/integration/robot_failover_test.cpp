// RobotClient with several hosts (DbSettings::hosts) against the real server and MariaDB:
// the first host is a TCP relay to the database that the test breaks at chosen moments,
// the second the database itself. A broken connection moves the robot to the next host
// by itself, and a request in flight is neither lost nor sent twice (SPEC 5.3):
//   * the INSERT reached the database and committed, its OK never came back: the client
//     finds it (rr_mine / sa_mine) and does not send it again; one row, one answer;
//   * the INSERT never reached the database: the client sends it again; one answer;
//   * a host that refuses connections is skipped, at start and on failover.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <thread>

#include <gtest/gtest.h>

#include "client/robot_client.h"
#include "protocol/connection.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

// Relays one TCP connection at a time to 127.0.0.1:upstream. Armed, it breaks the
// connection that carries the next "INSERT INTO rr": before passing it on (the request
// never reaches the database), or after passing it on, in place of the database's reply
// (the request commits; the robot never hears so).
class BreakingRelay {
 public:
  enum class Break { None, BeforeInsert, InsteadOfReply };

  explicit BreakingRelay(unsigned upstream) : upstream_(upstream) {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    if (::bind(listener_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(listener_, 8) != 0)
      throw std::runtime_error("relay: cannot listen");
    socklen_t len = sizeof a;
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~BreakingRelay() {
    stop_ = true;
    ::shutdown(listener_, SHUT_RDWR);
    ::close(listener_);
    thread_.join();
  }
  unsigned port() const { return port_; }
  void arm(Break b) { armed_ = b; }
  size_t breaks() const { return breaks_; }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{listener_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const int client = ::accept(listener_, nullptr, nullptr);
      if (client < 0) continue;
      const int db = ::socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in a{};
      a.sin_family = AF_INET;
      a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      a.sin_port = htons(static_cast<uint16_t>(upstream_));
      if (::connect(db, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) relay(client, db);
      ::close(db);
      ::close(client);
    }
  }
  void relay(int client, int db) {
    bool break_on_reply = false;
    char buf[65536];
    while (!stop_) {
      pollfd p[2] = {{client, POLLIN, 0}, {db, POLLIN, 0}};
      if (::poll(p, 2, 50) <= 0) continue;
      if (p[0].revents) {
        const ssize_t n = ::recv(client, buf, sizeof buf, 0);
        if (n <= 0) return;
        const bool insert = ::memmem(buf, static_cast<size_t>(n), "INSERT INTO rr", 14) != nullptr;
        if (insert && armed_ == Break::BeforeInsert) {
          armed_ = Break::None;
          ++breaks_;
          return;  // closed: the INSERT never went on
        }
        if (insert && armed_ == Break::InsteadOfReply) {
          armed_ = Break::None;
          break_on_reply = true;
        }
        if (::send(db, buf, static_cast<size_t>(n), MSG_NOSIGNAL) != n) return;
      }
      if (p[1].revents) {
        const ssize_t n = ::recv(db, buf, sizeof buf, 0);
        if (n <= 0) return;
        if (break_on_reply) {
          ++breaks_;
          return;  // the INSERT's OK is dropped with the connection
        }
        if (::send(client, buf, static_cast<size_t>(n), MSG_NOSIGNAL) != n) return;
      }
    }
  }

  unsigned upstream_;
  int listener_ = -1;
  unsigned port_ = 0;
  std::atomic<Break> armed_{Break::None};
  std::atomic<size_t> breaks_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// A port nothing listens on: bound, never listening.
class DeadPort {
 public:
  DeadPort() {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a);
    socklen_t len = sizeof a;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
  }
  ~DeadPort() { ::close(fd_); }
  unsigned port() const { return port_; }

 private:
  int fd_ = -1;
  unsigned port_ = 0;
};

class RobotFailover : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map("failover_map");
    const std::string pw = add_robot("failover_r1", "failover_map");
    robot_id_ = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'failover_r1'"));
    settings_ = tcp_settings(Role::Inspector);
    settings_.user = "failover_r1";
    settings_.password = pw;
    write_file(temp_path("failover_server.log"), "");
    server_ = std::make_unique<ServerProcess>("--poll-max-ms 5", "failover_server.log");
  }
  void TearDown() override {
    server_.reset();
    if (HasFailure()) std::cerr << read_file(temp_path("failover_server.log")).substr(0, 20000);
    run("fleetmap", "robot remove failover_r1");
  }
  // The request's answers that reach the robot (await), and then anything more within a while.
  size_t answers_to(RobotClient& c, unsigned long long request) {
    size_t n = c.await(request, 1, std::chrono::seconds(15)).size();
    for (int i = 0; i < 30; ++i) {
      for (const ReceivedAnswer& a : c.receive()) n += a.request_id == request;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return n;
  }

  DbSettings settings_;
  unsigned robot_id_ = 0;
  std::unique_ptr<ServerProcess> server_;
};

TEST_F(RobotFailover, ACommittedInsertWhoseReplyWasLostIsNotSentAgain) {
  BreakingRelay relay(settings_.port);
  DeadPort dead;
  // The dead host first: the client starts on the relay, skipping it.
  settings_.hosts = {{"127.0.0.1", dead.port()}, {"127.0.0.1", relay.port()}, {"127.0.0.1", settings_.port}};
  RobotClient client(settings_, std::chrono::seconds(20));
  EXPECT_EQ(client.node(), "127.0.0.1:" + std::to_string(relay.port()));
  client.ready(71);
  // The server off: the request must stay in rr, where the check finds it.
  server_->terminate();
  const long long before = scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'failover_r1'");
  relay.arm(BreakingRelay::Break::InsteadOfReply);
  const unsigned long long id = client.send(RequestOp::GetPosEnd);
  EXPECT_EQ(relay.breaks(), 1u);
  EXPECT_EQ(client.in_doubt(), 1u);
  EXPECT_EQ(client.found_committed(), 1u);
  // Back through the relay: the same node first, where the broken connection's
  // statement is waited for until it is gone.
  EXPECT_EQ(client.node(), "127.0.0.1:" + std::to_string(relay.port()));
  EXPECT_GE(client.reconnects(), 1u);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'failover_r1'"), before + 1) << "sent twice, or not at all";
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id = " + std::to_string(id) + " AND db_user = 'failover_r1'"), 1)
      << "send() returned another id than the committed request's";
  server_ = std::make_unique<ServerProcess>("--poll-max-ms 5", "failover_server.log");
  EXPECT_EQ(answers_to(client, id), 1u);
}

TEST_F(RobotFailover, AnAnsweredInsertWhoseReplyWasLostIsFoundByItsAnswer) {
  BreakingRelay relay(settings_.port);
  settings_.hosts = {{"127.0.0.1", relay.port()}, {"127.0.0.1", settings_.port}};
  RobotClient client(settings_, std::chrono::seconds(20));
  client.ready(72);
  // The server running: by the time the client looks, the request waits in rr_mine or is
  // answered in sa_mine; either way it is found, not sent again.
  relay.arm(BreakingRelay::Break::InsteadOfReply);
  const unsigned long long id = client.send(RequestOp::GetPosEnd);
  EXPECT_EQ(client.found_committed(), 1u);
  EXPECT_EQ(answers_to(client, id), 1u);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE db_user = 'failover_r1' AND sentinel = 0"), 0)
      << "answers left behind";
}

TEST_F(RobotFailover, AnInsertThatNeverArrivedIsSentAgainOnce) {
  BreakingRelay relay(settings_.port);
  settings_.hosts = {{"127.0.0.1", relay.port()}, {"127.0.0.1", settings_.port}};
  RobotClient client(settings_, std::chrono::seconds(20));
  client.ready(73);
  server_->terminate();
  const long long before = scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'failover_r1'");
  relay.arm(BreakingRelay::Break::BeforeInsert);
  const unsigned long long id = client.send(RequestOp::GetPosEnd);
  EXPECT_EQ(relay.breaks(), 1u);
  EXPECT_EQ(client.in_doubt(), 1u);
  EXPECT_EQ(client.found_committed(), 0u);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'failover_r1'"), before + 1);
  server_ = std::make_unique<ServerProcess>("--poll-max-ms 5", "failover_server.log");
  EXPECT_EQ(answers_to(client, id), 1u);
}

TEST_F(RobotFailover, NoHostAnsweringIsAClearErrorNamingThem) {
  DeadPort a, b;
  settings_.hosts = {{"127.0.0.1", a.port()}, {"127.0.0.1", b.port()}};
  try {
    RobotClient client(settings_, std::chrono::seconds(1));
    FAIL() << "connected to nothing";
  } catch (const DbError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no database node answers"), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(a.port())), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(b.port())), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace fleetmap::test
