#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/core/input_error.h"
#include "pirouette/eval/segmentation_eval.h"
#include "pirouette/tools/segment_eval.h"

namespace pirouette::cli {

Command AddSegmentEvalCommand(CLI::App& parent) {
  auto request = std::make_shared<eval::SegmentationEvalRequest>();
  auto method = std::make_shared<std::string>("default");
  auto sim_request = std::make_shared<eval::SimulatedEvalRequest>();
  CLI::App* cmd = parent.add_subcommand(
      "segment-eval",
      "Measure floor segmentation, as the mean and per-frame IoU of the floor mask (JSON on "
      "standard output): on photos with hand-made floor masks (source_N.bmp, gt_source_N.bmp), "
      "or on simulated frames of a world against the ray caster's truth.\n  example: pirouette "
      "segment-eval --images ../shared/realdata/visar --first 70 --last 99\n  example: "
      "pirouette segment-eval --world worlds/apartment.yaml --stops 3");
  CLI::Option* images =
      cmd->add_option("--images", request->images_dir, "the folder of photos and masks");
  CLI::Option* world =
      AddWorldOption(cmd, sim_request->world_path, "measure on its simulated frames instead");
  images->excludes(world);
  cmd->add_option("--stops", sim_request->stops,
                  "with --world: pirouettes at this many poses besides the start")
      ->capture_default_str();
  cmd->add_option("--frames-dir", sim_request->frames_dir,
                  "with --world: write each frame's overlay and true mask to this folder");
  AddSeedOption(cmd, sim_request->seed, "the random poses and the simulator's noise, with --world");
  AddMethodOption(cmd, *method, kSegmentationMethods);
  cmd->add_option("--first", request->first, "the first photo's number")->capture_default_str();
  cmd->add_option("--last", request->last, "the last photo's number")->capture_default_str();
  return {cmd, [request, method, sim_request, images, world] {
            request->method = *vision::ParseSegmentationMethod(*method);
            const std::string name(vision::SegmentationMethodName(request->method));
            if (world->count() > 0) {
              sim_request->method = request->method;
              const eval::SegmentationEvalResult result =
                  eval::EvaluateSimulatedSegmentation(*sim_request);
              request->first = 0;
              request->last = static_cast<int>(result.images.size()) - 1;
              std::fputs(tools::SegmentationEvalJson(*request, result).c_str(), stdout);
              std::fprintf(stderr,
                           "%s, %s, %zu frames: mean IoU %.4f, boundary row error median %.0f "
                           "px, p95 %.0f px\n",
                           name.c_str(), sim_request->world_path.c_str(), result.images.size(),
                           result.mean_iou, result.boundary_error_median_px.value_or(0.0),
                           result.boundary_error_p95_px.value_or(0.0));
              return;
            }
            if (images->count() == 0) {
              throw core::InputError("", 0, "--images", "give --images DIR or --world FILE");
            }
            const eval::SegmentationEvalResult result = eval::EvaluateSegmentation(*request);
            std::fputs(tools::SegmentationEvalJson(*request, result).c_str(), stdout);
            std::fprintf(stderr, "%s, photos %d-%d: mean IoU %.4f\n", name.c_str(), request->first,
                         request->last, result.mean_iou);
          }};
}

}  // namespace pirouette::cli
