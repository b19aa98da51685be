#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "apps/pirouette/options.h"
#include "pirouette/core/input_error.h"
#include "pirouette/core/odometry_noise.h"
#include "pirouette/run/log_replay.h"

namespace pirouette::cli {

Command AddMapCommand(CLI::App& parent) {
  auto request = std::make_shared<run::MapLogRequest>();
  auto ros2 = std::make_shared<Ros2Choices>();
  auto view = std::make_shared<ViewChoices>();
  // {} or {translation, rotation} each.
  auto noise = std::make_shared<std::vector<double>>();
  auto bias = std::make_shared<std::vector<double>>();
  CLI::App* cmd = parent.add_subcommand(
      "map",
      "Build the map of a recorded run (a pirouette-log/1 folder, as `explore --record DIR` "
      "writes one or a script on a real robot does; docs/run-log.md): each frame is segmented "
      "and its obstacle profile put in the occupancy grid at its odometry, in order, exactly as "
      "the run did. Writes OUT/map.yaml + map.pgm, map.png, map_colours.png and run.json (with the "
      "map's evaluation when the log's world, or --world, is known). The settings default to the "
      "log's own (log.yaml). A log cut short (a run killed while it recorded: frames.csv's last "
      "row without its line end, a frame missing or cut) maps every frame before the cut, says "
      "where it stopped, and ends with status `truncated`.\n"
      "With --odometry-noise (and --odometry-bias) the log's odometry is taken as the truth "
      "(record it without noise) and the frames are mapped at the odometry a robot with that "
      "error would have reported, drawn from --seed, the simulator's motion model turned round: "
      "run.json gives the pose error and the loop closures against the truth, so a localization "
      "can be tried under drift in seconds, without rendering (docs/measurements.md, \"Pose "
      "graph\").\n"
      "Exit: 0 done (also for a cut log), 1 failed, 2 bad input.\n"
      "  example: pirouette explore --world worlds/soccer_field.yaml --record run1 && "
      "pirouette map --log run1 --out map1\n"
      "  example: pirouette map --log run1 --odometry-noise 0.05,0.05 --odometry-bias 0.02,0.01 "
      "--seed 3 --out drift3");
  cmd->add_option("--log", request->log_dir, "the run log's folder")->required();
  AddOutFolderOption(cmd, request->out_dir);
  AddWorldOption(cmd, request->world_path,
                 "the map is evaluated against it (default: the log's world, if it exists)");
  AddRadiusOption(cmd, request->radius_m, "the log's robot.radius");
  AddCellOption(cmd, request->cell_m, "the log's");
  AddMaxRangeOption(cmd, request->max_range_m, "the log's, else the paper's rule");
  AddMaxMapOption(cmd, request->max_map_m, "ends the mapping there (status truncated)");
  AddMethodOption(cmd, request->method, kSegmentationMethods, "the log's");
  AddLocalizeOption(cmd, request->localize, "the log's, else graph");
  cmd->add_option("--odometry-noise", *noise,
                  "T,R: map the log at odometry drifted from it, with these standard deviations "
                  "of a straight move's error as a fraction of its length and of a turn's as a "
                  "fraction of its angle, e.g. 0.05,0.05 (default: the log's odometry as it is)")
      ->delimiter(',')
      ->expected(2);
  cmd->add_option("--odometry-bias", *bias,
                  "T,R: with --odometry-noise, a constant error added to those fractions (wheels "
                  "that drift one way), e.g. 0.02,0.01 (default 0,0)")
      ->delimiter(',')
      ->expected(2);
  AddSeedOption(cmd, request->seed, "the drifted odometry (--odometry-noise)");
  AddRos2PublishOptions(cmd, *ros2);
  AddViewOptions(cmd, *view, false);
  AddQuietOption(cmd, request->quiet);
  return {cmd, [request, ros2, view, noise, bias] {
            if (!bias->empty() && noise->empty()) {
              throw core::InputError("--odometry-bias", 0, "",
                                     "needs --odometry-noise (it drifts the log's odometry)");
            }
            if (!noise->empty()) {
              core::OdometryNoise drift{(*noise)[0], (*noise)[1], 0.0, 0.0};
              if (!bias->empty()) {
                drift.translation_bias = (*bias)[0];
                drift.rotation_bias = (*bias)[1];
              }
              request->odometry_noise = drift;
            }
            request->ros2_publish = Ros2PublishOf(*ros2);
            request->live_view = LiveViewOf(*view, ros2->ros_namespace);
            request->on_view = AnnounceView("map", request->quiet);
            request->stop_requested = StopOnInterrupt();
            const run::MapLogReport report = run::RunMapLog(*request);
            if (!request->quiet) {
              std::fprintf(stderr, "map: %d frames in %.1f s; map in %s/map.yaml\n",
                           report.result.frames, report.result.wall_time_s,
                           request->out_dir.c_str());
            }
            if (report.result.status == "truncated") {
              // A warning, not a failure: the map of every whole frame is written.
              std::fprintf(stderr, "map: the log stops short: %s\n", report.result.reason.c_str());
            }
            if (report.result.status == "interrupted") {
              throw std::runtime_error("interrupted; the map of the frames before is in " +
                                       request->out_dir);
            }
          }};
}

}  // namespace pirouette::cli
