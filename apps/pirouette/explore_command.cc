#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "pirouette/run/explore_job.h"

namespace pirouette::cli {

Command AddExploreCommand(CLI::App& parent) {
  auto request = std::make_shared<run::ExploreRequest>();
  auto planner = std::make_shared<std::string>("dt");
  auto method = std::make_shared<std::string>("default");
  auto localize = std::make_shared<std::string>("none");
  CLI::App* cmd = parent.add_subcommand(
      "explore",
      "Drop the robot (simulated, or a real one with --robot) into a world knowing nothing and let "
      "it map the floor by itself: "
      "it pirouettes (12 frames, 30 degrees apart), maps the floor's edges, plans the shortest "
      "safe path to the nearest unknown space, looks before every move, and stops when no "
      "reachable unknown space is left. Writes OUT/map.yaml + map.pgm (ROS map_server), "
      "map.png, map_colours.png (the colours seen on the map's walls, for locate), run.json (with "
      "the map's evaluation against the world) and, with --video, "
      "explore.mp4. Ctrl-C stops and still writes the map so far.\n"
      "Exit: 0 complete or step limit, 1 stuck or interrupted (outputs still written), 2 bad "
      "input.\n  example: pirouette explore --world worlds/soccer_field.yaml --out out --video\n"
      "  a real robot: pirouette explore --robot tcp://192.168.1.20:5555 --camera cam.yaml "
      "--radius 0.15 --record run1");
  cmd->add_option("--world", request->world_path,
                  "world file (pirouette-world/1); with --robot only for the camera, the radius "
                  "and the evaluation");
  cmd->add_option("--out", request->out_dir, "output folder")->capture_default_str();
  cmd->add_option("--seed", request->options.seed,
                  "seed of the simulator's noise (camera and odometry)")
      ->capture_default_str();
  cmd->add_option("--max-steps", request->options.max_steps,
                  "stop after this many straight moves (status step-limit)")
      ->capture_default_str();
  cmd->add_option("--planner", *planner,
                  "dt: the paper's distance transform to the nearest unknown space; frontier: "
                  "the explore_lite baseline")
      ->check(CLI::IsMember({"dt", "frontier"}))
      ->capture_default_str();
  cmd->add_option("--method", *method, "floor segmentation: default or paper")
      ->check(CLI::IsMember({"default", "paper"}))
      ->capture_default_str();
  cmd->add_option("--localize", *localize,
                  "none: trust the odometry; scan: correct each frame's heading by matching "
                  "what the camera sees against the earlier frames of the stop and the map made "
                  "before it, turning in steps of a pirouette's with a look after each, and each "
                  "whole pirouette's position and heading by scan matching its hits against those "
                  "of the stops before (cuts pose error and false free cells under wheel slip, "
                  "costs a little without it: see the README's localization figures)")
      ->check(CLI::IsMember({"scan", "none"}))
      ->capture_default_str();
  cmd->add_option("--cell", request->options.cell_m,
                  "map cell, metres (default: 0.01 for a robot under 0.1 m radius, else 0.02)");
  cmd->add_option("--max-range", request->options.max_range_m,
                  "trust readings out to this range, metres (default: the paper's rule for the "
                  "camera and cell)");
  cmd->add_flag("--return-home", request->options.return_home,
                "drive back to the start when the map is complete");
  auto noise = std::make_shared<std::vector<double>>();
  auto bias = std::make_shared<std::vector<double>>();
  CLI::Option* noise_option =
      cmd->add_option("--odometry-noise", *noise,
                      "T,R: the simulator's motion error, standard deviations as fractions of "
                      "each straight move's length and each turn's angle (default: the world "
                      "file's odometry_noise)")
          ->delimiter(',')
          ->expected(2);
  CLI::Option* bias_option =
      cmd->add_option("--odometry-bias", *bias,
                      "T,R: a constant error added to those fractions (wheels that drift one "
                      "way), e.g. 0.02,-0.01 (default: the world file's)")
          ->delimiter(',')
          ->expected(2);
  cmd->add_flag("--video", request->video, "also write OUT/explore.mp4");
  cmd->add_option("--robot", request->robot_url,
                  "explore with a robot that speaks the line protocol at tcp://HOST:PORT "
                  "(docs/robot-protocol.md; `pirouette sim-serve` serves the simulator so) "
                  "instead of in the simulator");
  cmd->add_option("--camera", request->camera_path,
                  "the robot's camera file (default: the world's robot camera)");
  cmd->add_option("--radius", request->radius_m,
                  "the robot's radius, metres (default: the world's robot)");
  cmd->add_option("--robot-timeout", request->robot_timeout_s,
                  "seconds to wait for the robot's reply before giving up (the map so far is "
                  "written)")
      ->capture_default_str();
  cmd->add_option("--record", request->record_dir,
                  "also write a run log (pirouette-log/1: camera.yaml, frames/, frames.csv) in "
                  "this new folder; `pirouette map --log DIR` maps it again");
  cmd->add_flag("--quiet", request->quiet, "no progress on standard error");
  return {cmd, [request, planner, method, localize, noise, bias, noise_option, bias_option] {
            request->options.localize = *run::ParseLocalizeKind(*localize);
            if (noise_option->count() > 0) request->odometry_noise = {(*noise)[0], (*noise)[1]};
            if (bias_option->count() > 0) request->odometry_bias = {(*bias)[0], (*bias)[1]};
            request->options.planner = *run::ParsePlannerKind(*planner);
            request->options.method = *vision::ParseMaskSource(*method);
            request->options.stop_requested = StopOnInterrupt();
            const run::ExploreReport report = run::RunExplore(*request);
            const std::string& status = report.result.status;
            if (!request->quiet) {
              std::fprintf(stderr, "explore: %s; map in %s/map.yaml\n", status.c_str(),
                           request->out_dir.c_str());
            }
            if (status == "stuck") throw std::runtime_error("stuck: " + report.result.reason);
            if (!report.record_error.empty()) {
              throw std::runtime_error("the run log in " + request->record_dir +
                                       " is incomplete: " + report.record_error);
            }
            if (status == "interrupted") {
              throw std::runtime_error("interrupted; the map so far is in " + request->out_dir);
            }
          }};
}

}  // namespace pirouette::cli
