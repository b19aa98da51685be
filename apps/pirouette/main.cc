// The command line of pirouette: parsing, messages and exit codes (SPEC.md:
// 0 done, 1 the run failed, 2 bad usage or bad input). The work is in app/.

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "pirouette/app/render_view.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/sim/renderer.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

// Parses "X,Y,HEADING" (metres, metres, degrees).
pirouette::core::Pose2 ParsePose(const std::string& text) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    double value = 0.0;
    const char* first = text.data() + start;
    const char* last = text.data() + comma;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || first == last) {
      throw pirouette::core::InputError(
          "--pose", 0, "", "expected X,Y,HEADING (metres, metres, degrees), got '" + text + "'");
    }
    values.push_back(value);
    start = comma + 1;
  }
  if (values.size() != 3) {
    throw pirouette::core::InputError("--pose", 0, "",
                                      "expected three numbers X,Y,HEADING, got '" + text + "'");
  }
  return {values[0], values[1], pirouette::core::DegToRad(values[2])};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "pirouette: a robot with one cheap camera maps an unknown floor by itself.\n"
      "It spins on the spot, finds where the floor ends in each picture, turns that\n"
      "edge into ranges, and builds an occupancy grid (Taylor, Geva & Boles, 2005).\n"};
  app.require_subcommand(1);
  app.failure_message(CLI::FailureMessage::help);

  pirouette::app::RenderViewRequest render;
  std::string render_pose;
  CLI::App* render_cmd = app.add_subcommand(
      "render",
      "Write what the robot's camera sees at a pose, with its lens distortion, vignetting and "
      "noise, as a PNG.\n  example: pirouette render --world worlds/soccer_field.yaml "
      "--pose 0.2,0.2,45 --out view.png");
  render_cmd->add_option("--world", render.world_path, "world file (pirouette-world/1 YAML)")
      ->required();
  render_cmd
      ->add_option("--pose", render_pose,
                   "X,Y,HEADING: metres, metres, degrees counter-clockwise from +x")
      ->required();
  render_cmd->add_option("--out", render.out_path, "the PNG to write")->required();
  render_cmd->add_option("--seed", render.seed, "seeds the sensor noise")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  try {
    if (*render_cmd) {
      render.world_T_robot = ParsePose(render_pose);
      pirouette::app::RenderView(render);
      std::fprintf(stderr, "wrote %s\n", render.out_path.c_str());
    }
    return kExitOk;
  } catch (const pirouette::core::InputError& e) {
    std::fprintf(stderr, "pirouette: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pirouette: %s\n", e.what());
    return kExitFailed;
  }
}
