#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "pirouette/core/input_error.h"
#include "pirouette/tools/segment.h"

namespace pirouette::cli {

Command AddSegmentCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::SegmentImageRequest>();
  auto method = std::make_shared<std::string>("default");
  auto max_range = std::make_shared<double>(0.0);
  CLI::App* cmd = parent.add_subcommand(
      "segment",
      "Find the floor in one photo: write its mask and an overlay, and with a camera print the "
      "obstacle profile (one reading per column) as JSON on standard output.\n  example: "
      "pirouette segment --image view.png --camera worlds/yujin.yaml --mask mask.png --out "
      "overlay.png");
  cmd->add_option("--image", request->image_path, "the photo (any format OpenCV reads)")
      ->required();
  cmd->add_option("--camera", request->camera_path,
                  "camera file (ROS camera_info YAML); its size must be the image's");
  cmd->add_option("--method", *method, "paper | default")->capture_default_str();
  cmd->add_option("--mask", request->mask_path, "PNG to write the floor mask to (255 floor)");
  cmd->add_option("--out", request->overlay_path, "PNG to write the overlay picture to");
  CLI::Option* max_range_option = cmd->add_option(
      "--max-range", *max_range, "the profile's maximum range, metres (default: the camera's)");
  return {cmd, [request, method, max_range, max_range_option] {
            const auto parsed = vision::ParseSegmentationMethod(*method);
            if (!parsed) {
              throw core::InputError("", 0, "--method",
                                     "'" + *method + "' is not a method (paper | default)");
            }
            request->method = *parsed;
            if (max_range_option->count() > 0) request->max_range_m = *max_range;
            const tools::SegmentImageResult result = tools::SegmentImage(*request);
            if (result.profile) {
              std::fputs(tools::ObstacleProfileJson(*result.profile).c_str(), stdout);
            }
            if (!request->mask_path.empty()) {
              std::fprintf(stderr, "wrote %s\n", request->mask_path.c_str());
            }
            if (!request->overlay_path.empty()) {
              std::fprintf(stderr, "wrote %s\n", request->overlay_path.c_str());
            }
          }};
}

}  // namespace pirouette::cli
