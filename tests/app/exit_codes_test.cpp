// app/exit_code_for.h: each exception class ends a program with the code of README
// "Exit codes"; run_program turns a thrown exception or a parse error into that code.
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <mysql++/mysql++.h>

#include "app/exit_code_for.h"
#include "app/run_program.h"
#include "client/robot_client.h"
#include "common/core/error.h"
#include "common/io/scene_geojson.h"
#include "common/io/seed_format.h"
#include "common/io/topo_json.h"
#include "common/planning/topo_graph.h"
#include "protocol/connection.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "protocol/params.h"
#include "protocol/scene_store.h"
#include "protocol/topo_store.h"

namespace fleetmap {
namespace {

// The README's table, written out here rather than taken from app/exit_codes.h, so that a
// changed constant fails the test.
constexpr int kFailure = 1, kBadInput = 2, kNoPath = 3, kNotFound = 4, kLocalization = 5, kUsage = 64;

TEST(ExitCodeFor, TheRootClasses) {
  EXPECT_EQ(exit_code_for(BadInput("x")), kBadInput);
  EXPECT_EQ(exit_code_for(FileFormatError("f:1: x")), kBadInput);
  EXPECT_EQ(exit_code_for(NoPath("x")), kNoPath);
  EXPECT_EQ(exit_code_for(NotFound("x")), kNotFound);
  EXPECT_EQ(exit_code_for(Failure("x")), kFailure);
  EXPECT_EQ(exit_code_for(IoError("x")), kFailure);
  EXPECT_EQ(exit_code_for(UsageError("x")), kUsage);
  EXPECT_EQ(exit_code_for(LocalizationFailed("x")), kLocalization);
  EXPECT_EQ(exit_code_for(Error("x")), kFailure);
}

TEST(ExitCodeFor, MalformedInputIsTwo) {
  EXPECT_EQ(exit_code_for(MapFormatError("a.map", 3, "expected a number")), kBadInput);
  EXPECT_EQ(exit_code_for(TopoFormatError("g.json", "nodes[0]", "expected an id")), kBadInput);
  EXPECT_EQ(exit_code_for(SceneFormatError(2, "properties.z", "expected 2 ranges")), kBadInput);
  EXPECT_EQ(exit_code_for(TopoGraphError("edge 1: expected two different nodes")), kBadInput);
  EXPECT_EQ(exit_code_for(UnknownTag("sofa", "o1")), kBadInput);
  EXPECT_EQ(exit_code_for(ProtocolError(ErrorCode::BadParams, "expected x")), kBadInput);
  // What library functions throw for a value they refuse (common/, server_config).
  EXPECT_EQ(exit_code_for(std::invalid_argument("expected a radius >= 0")), kBadInput);
}

TEST(ExitCodeFor, MissingOrExistingIsFour) {
  EXPECT_EQ(exit_code_for(MapNotFound("m")), kNotFound);
  EXPECT_EQ(exit_code_for(MapExists("m")), kNotFound);
  EXPECT_EQ(exit_code_for(RobotNotFound("r")), kNotFound);
  EXPECT_EQ(exit_code_for(TopoGraphNotFound("m")), kNotFound);
  EXPECT_EQ(exit_code_for(TopoGraphExists("m")), kNotFound);
  EXPECT_EQ(exit_code_for(TopoNodeNotFound(7)), kNotFound);
  EXPECT_EQ(exit_code_for(SceneKeyExists("m", "object", "k")), kNotFound);
}

TEST(ExitCodeFor, DatabaseAndEverythingElseIsOne) {
  EXPECT_EQ(exit_code_for(DbError("cannot connect")), kFailure);
  EXPECT_EQ(exit_code_for(RobotClientError("no answer")), kFailure);
  EXPECT_EQ(exit_code_for(mysqlpp::ConnectionFailed("Can't connect to server")), kFailure);
  EXPECT_EQ(exit_code_for(mysqlpp::BadQuery("syntax error")), kFailure);
  EXPECT_EQ(exit_code_for(std::runtime_error("x")), kFailure);
  EXPECT_EQ(exit_code_for(std::logic_error("x")), kFailure);
  // Not std::invalid_argument: an internal error, not the user's input.
  EXPECT_EQ(exit_code_for(std::out_of_range("x")), kFailure);
}

TEST(ExitCodeFor, ParseErrorsAreUsageAndHelpIsZero) {
  EXPECT_EQ(exit_code_for(CLI::ExtrasError({"--bogus"})), kUsage);
  EXPECT_EQ(exit_code_for(CLI::RequiredError("--name")), kUsage);
  EXPECT_EQ(exit_code_for(CLI::ValidationError("expected X Y")), kUsage);
  EXPECT_EQ(exit_code_for(CLI::CallForHelp()), 0);
}

TEST(ErrorMessage, SaysADatabaseErrorIsOne) {
  EXPECT_EQ(error_message(mysqlpp::ConnectionFailed("Can't connect to server")),
            "database error: Can't connect to server");
  EXPECT_EQ(error_message(MapNotFound("m")), "no map named 'm'");
}

// run_program with a throwaway App: argv as the program gets it.
struct Program {
  CLI::App app{"test program"};
  std::string out, err;
  int run(std::vector<std::string> args, const std::function<int()>& body) {
    args.insert(args.begin(), "prog");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const int code = run_program("prog", app, static_cast<int>(argv.size()), argv.data(), body);
    out = testing::internal::GetCapturedStdout();
    err = testing::internal::GetCapturedStderr();
    return code;
  }
};

TEST(RunProgram, ReturnsWhatTheBodyReturns) {
  Program p;
  EXPECT_EQ(p.run({}, [] { return 3; }), 3);
  EXPECT_EQ(p.err, "");
}

TEST(RunProgram, PrintsTheMessageWithTheProgramName) {
  Program p;
  EXPECT_EQ(p.run({}, []() -> int { throw MapNotFound("campus"); }), kNotFound);
  EXPECT_EQ(p.err, "prog: no map named 'campus'\n");
}

TEST(RunProgram, PrintsAFileErrorAsIsForEditors) {
  Program p;
  EXPECT_EQ(p.run({}, []() -> int { throw MapFormatError("a.map", 12, "expected ';'"); }), kBadInput);
  EXPECT_EQ(p.err, "a.map:12: expected ';'\n");
}

TEST(RunProgram, AnUnknownOptionIsUsageWithCli11sMessage) {
  Program p;
  bool ran = false;
  EXPECT_EQ(p.run({"--bogus"}, [&] { ran = true; return 0; }), kUsage);
  EXPECT_FALSE(ran);
  EXPECT_NE(p.err.find("--bogus"), std::string::npos) << p.err;
}

TEST(RunProgram, HelpIsZeroOnStandardOutput) {
  Program p;
  int n = 0;
  p.app.add_option("-n", n, "a number");
  EXPECT_EQ(p.run({"--help"}, [] { return 9; }), 0);
  EXPECT_NE(p.out.find("a number"), std::string::npos) << p.out;
}

TEST(RunProgram, ACallbackThrowingDuringParseIsMappedToo) {
  Program p;
  auto* sub = p.app.add_subcommand("go", "");
  sub->callback([] { throw NoPath("no path from A to B"); });
  EXPECT_EQ(p.run({"go"}, [] { return 0; }), kNoPath);
  EXPECT_EQ(p.err, "prog: no path from A to B\n");
}

}  // namespace
}  // namespace fleetmap
