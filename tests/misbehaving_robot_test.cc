// Robots that misbehave (`pirouette sim-serve --fault KIND[@N]`), over TCP and
// over DDS: each run ends by itself with a clear status and reason and the
// map so far written (or, for a fault pirouette can carry on through, ends
// as a run does); none hangs, none crashes. docs/robot-protocol.md and
// docs/ros2.md list what pirouette does with each fault.

#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/testing/temp_dir.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace pirouette::misbehaving_robot_test {
namespace {

namespace fs = std::filesystem;

// Ports and DDS domains of these tests: each test its own, so that they may
// run side by side.
constexpr int kFirstPort = 18800;
constexpr int kFirstDomain = 150;
// Far past what any of these runs takes: a run still going then has hung.
constexpr int kHangS = 180;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

struct Ended {
  int exit_code = -1;  // 124: killed by the hang bound
  std::string stderr_text;
};

// Runs `pirouette args` (with ROS_DOMAIN_ID `domain`, if ≥ 0), killed if it
// has not ended within kHangS.
Ended RunPirouette(const std::string& args, const fs::path& err, int domain = -1) {
  const std::string env = domain >= 0 ? "ROS_DOMAIN_ID=" + std::to_string(domain) + " " : "";
  const std::string command = env + "timeout -k 5 " + std::to_string(kHangS) + " " +
                              PIROUETTE_BINARY + " " + args + " >/dev/null 2>" + err.string();
  Ended run;
  const int status = std::system(command.c_str());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  run.stderr_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return run;
}

// `pirouette sim-serve ...` in the background, stopped (SIGINT) when the
// object goes.
class SimServe {
 public:
  SimServe(std::vector<std::string> args, int domain) {
    args.insert(args.begin(), {PIROUETTE_BINARY, "sim-serve"});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_strings;
    for (char** e = environ; *e != nullptr; ++e) {
      if (std::string(*e).rfind("ROS_DOMAIN_ID=", 0) != 0) env_strings.emplace_back(*e);
    }
    if (domain >= 0) env_strings.push_back("ROS_DOMAIN_ID=" + std::to_string(domain));
    std::vector<char*> envp;
    for (std::string& e : env_strings) envp.push_back(e.data());
    envp.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), envp.data()) != 0) pid_ = 0;
  }
  ~SimServe() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGINT);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  SimServe(const SimServe&) = delete;
  SimServe& operator=(const SimServe&) = delete;

  bool started() const { return pid_ > 0; }

 private:
  pid_t pid_ = 0;
};

class MisbehavingRobot : public ::testing::Test {
 protected:
  // sim-serve on `port` with `fault`; true once it listens.
  bool ServeTcp(int port, const std::string& fault) {
    const std::string port_file = dir_ / "port";
    std::vector<std::string> args = {
        "--world", World("soccer_field"), "--port", std::to_string(port), "--port-file", port_file};
    if (!fault.empty()) args.insert(args.end(), {"--fault", fault});
    server_ = std::make_unique<SimServe>(args, -1);
    for (int i = 0; i < 600 && !fs::exists(port_file); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return server_->started() && fs::exists(port_file);
  }

  void ServeDds(int domain, const std::string& fault) {
    std::vector<std::string> args = {"--world", World("soccer_field"), "--ros2", "--ros-namespace",
                                     "bot"};
    if (!fault.empty()) args.insert(args.end(), {"--fault", fault});
    server_ = std::make_unique<SimServe>(args, domain);
  }

  Ended ExploreTcp(int port, const std::string& out, const std::string& extra = "") {
    return RunPirouette("explore --robot tcp://127.0.0.1:" + std::to_string(port) + " --world " +
                            World("soccer_field") + " --out " + (dir_ / out) + " --quiet " + extra,
                        dir_.path() / (out + ".err"));
  }

  Ended ExploreDds(int domain, const std::string& extra = "", const std::string& out = "out") {
    return RunPirouette("explore --robot ros2 --ros-namespace bot --localize none --world " +
                            World("soccer_field") + " --out " + (dir_ / out) + " --quiet " + extra,
                        dir_.path() / (out + ".err"), domain);
  }

  // The run ended stuck, saying `reason`, with the map so far and run.json.
  void ExpectStuckWithTheMapSoFar(const Ended& run, const std::string& reason,
                                  const std::string& out = "out") {
    ASSERT_NE(run.exit_code, 124) << "the run hung: " << run.stderr_text;
    EXPECT_EQ(run.exit_code, 1) << run.stderr_text;
    ASSERT_TRUE(fs::exists(dir_.path() / out / "run.json")) << run.stderr_text;
    const nlohmann::json result = nlohmann::json::parse(dir_.Read(out + "/run.json"));
    EXPECT_EQ(result["status"], "stuck") << result.dump(2);
    EXPECT_NE(result.value("reason", "").find(reason), std::string::npos) << result.dump(2);
    EXPECT_TRUE(fs::exists(dir_.path() / out / "map.pgm"));
    EXPECT_TRUE(fs::exists(dir_.path() / out / "map.yaml"));
    EXPECT_GT(result["frames"].get<int>(), 0);
  }

  // The run ended as runs do (complete or step-limit), with its outputs.
  void ExpectARun(const Ended& run, const std::string& out = "out") {
    ASSERT_NE(run.exit_code, 124) << "the run hung: " << run.stderr_text;
    EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
    ASSERT_TRUE(fs::exists(dir_.path() / out / "run.json")) << run.stderr_text;
    const nlohmann::json result = nlohmann::json::parse(dir_.Read(out + "/run.json"));
    EXPECT_TRUE(result["status"] == "complete" || result["status"] == "step-limit")
        << result.dump(2);
    EXPECT_TRUE(fs::exists(dir_.path() / out / "map.pgm"));
  }

  testing::TempDir dir_{"pirouette_misbehaving"};
  std::unique_ptr<SimServe> server_;
};

struct Fault {
  const char* fault;   // sim-serve --fault
  const char* reason;  // in run.json's reason
  int index;           // its port (kFirstPort + index) and DDS domain (kFirstDomain + index)
};

// For test names and messages: the fault as sim-serve takes it.
void PrintTo(const Fault& fault, std::ostream* out) { *out << fault.fault; }

std::string NameOf(const ::testing::TestParamInfo<Fault>& info) {
  std::string name;
  for (const char* c = info.param.fault; *c != '\0' && *c != '@'; ++c) {
    if (std::isalnum(static_cast<unsigned char>(*c)) != 0) name += *c;
  }
  return name;
}

// ---- over TCP ----

class TcpFault : public MisbehavingRobot, public ::testing::WithParamInterface<Fault> {};

TEST_P(TcpFault, EndsStuckWithAReasonAndTheMapSoFar) {
  const int port = kFirstPort + GetParam().index;
  ASSERT_TRUE(ServeTcp(port, GetParam().fault)) << "sim-serve did not start";
  // Short enough that the robot that hangs halfway through a frame is given
  // up soon, long enough for a first frame rendered on a loaded machine.
  const Ended run = ExploreTcp(port, "out", "--robot-timeout 10");
  ExpectStuckWithTheMapSoFar(run, GetParam().reason);
  EXPECT_NE(run.stderr_text.find("127.0.0.1:" + std::to_string(port)), std::string::npos)
      << run.stderr_text;
}

INSTANTIATE_TEST_SUITE_P(misbehaving, TcpFault,
                         ::testing::Values(Fault{"teleport@20", "odometry that jumped 1.", 0},
                                           Fault{"flip@20", "heading that jumped 180", 1},
                                           Fault{"clock-back@20", "its clock went backwards", 2},
                                           Fault{"same-frame@5", "its camera is frozen", 3},
                                           Fault{"late@20", "a late frame", 4},
                                           Fault{"out-of-order@20", "out of order", 5},
                                           Fault{"short-moves@5", "moves less than it is told", 6},
                                           Fault{"stalled@5", "did not move", 7},
                                           Fault{"half-frame@20", "frame answering CAPTURE", 8}),
                         NameOf);

// A second client while one drives the robot is refused at once, before it
// writes anything; the first drives on undisturbed.
TEST_F(MisbehavingRobot, ASecondTcpClientIsRefusedAndTheFirstGoesOn) {
  const int port = kFirstPort + 9;
  ASSERT_TRUE(ServeTcp(port, ""));
  std::future<Ended> first =
      std::async(std::launch::async, [&] { return ExploreTcp(port, "first", "--max-steps 4"); });
  // The first is connected once its output folder is made.
  for (int i = 0; i < 600 && !fs::exists(dir_ / "first"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const Ended second = ExploreTcp(port, "second");
  EXPECT_EQ(second.exit_code, 1) << second.stderr_text;
  EXPECT_NE(second.stderr_text.find("busy"), std::string::npos) << second.stderr_text;
  EXPECT_FALSE(fs::exists(dir_.path() / "second" / "map.pgm"));
  ExpectARun(first.get(), "first");
}

// ---- over DDS ----

class DdsFault : public MisbehavingRobot, public ::testing::WithParamInterface<Fault> {};

TEST_P(DdsFault, EndsStuckWithAReasonAndTheMapSoFar) {
  const int domain = kFirstDomain + GetParam().index;
  ServeDds(domain, GetParam().fault);
  ExpectStuckWithTheMapSoFar(ExploreDds(domain), GetParam().reason);
}

// The faults start a few simulated seconds in, after the first frames.
INSTANTIATE_TEST_SUITE_P(misbehaving, DdsFault,
                         ::testing::Values(Fault{"teleport@3", "jumped 1.", 0},
                                           Fault{"flip@3", "jumped", 1},
                                           Fault{"clock-back@3", "went backwards", 2},
                                           Fault{"same-frame@3", "its camera is frozen", 3},
                                           Fault{"stalled@3", "the robot does not move", 4}),
                         NameOf);

// A second run on the same robot is refused before it sends a command; the
// first drives on undisturbed.
TEST_F(MisbehavingRobot, ASecondDdsClientIsRefusedAndTheFirstGoesOn) {
  const int domain = kFirstDomain + 9;
  ServeDds(domain, "");
  std::future<Ended> first =
      std::async(std::launch::async, [&] { return ExploreDds(domain, "--max-steps 4", "first"); });
  for (int i = 0; i < 1500 && !fs::exists(dir_ / "first"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const Ended second = ExploreDds(domain, "", "second");
  EXPECT_EQ(second.exit_code, 1) << second.stderr_text;
  EXPECT_NE(second.stderr_text.find("another node already publishes on rt/bot/cmd_vel"),
            std::string::npos)
      << second.stderr_text;
  EXPECT_FALSE(fs::exists(dir_.path() / "second" / "map.pgm"));
  ExpectARun(first.get(), "first");
}

// Faults a run over DDS carries on through: moves are closed on odometry (a
// base that moves less than told is driven on until it is there), and only
// frames stamped after the robot came to rest are taken (a late or
// overtaken frame is waited out).
class DdsFaultCarriedOn : public MisbehavingRobot, public ::testing::WithParamInterface<Fault> {};

TEST_P(DdsFaultCarriedOn, EndsAsARunDoes) {
  const int domain = kFirstDomain + GetParam().index;
  ServeDds(domain, GetParam().fault);
  ExpectARun(ExploreDds(domain, "--max-steps 3"));
}

INSTANTIATE_TEST_SUITE_P(misbehaving, DdsFaultCarriedOn,
                         ::testing::Values(Fault{"late@1", "", 5}, Fault{"out-of-order@1", "", 6},
                                           Fault{"short-moves@1", "", 7}),
                         NameOf);

}  // namespace
}  // namespace pirouette::misbehaving_robot_test
