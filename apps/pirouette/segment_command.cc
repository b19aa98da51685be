#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/tools/segment.h"

namespace pirouette::cli {

Command AddSegmentCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::SegmentImageRequest>();
  auto method = std::make_shared<std::string>("default");
  CLI::App* cmd = parent.add_subcommand(
      "segment",
      "Find the floor in one photo: write its mask and an overlay, and with a camera print the "
      "obstacle profile (one reading per column) as JSON on standard output.\n  example: "
      "pirouette segment --image view.png --camera worlds/yujin.yaml --mask mask.png --out "
      "overlay.png");
  AddImageOption(cmd, request->image_path)->required();
  AddCameraOption(cmd, request->camera_path,
                  "its size must be the image's; without it: no correction and no profile");
  AddMethodOption(cmd, *method, kSegmentationMethods);
  cmd->add_option("--mask", request->mask_path, "PNG to write the floor mask to (255 floor)");
  AddOutPngOption(cmd, request->overlay_path, "the floor drawn over the photo");
  AddMaxRangeOption(cmd, request->max_range_m, "the camera's, by the paper's rule for 1 cm cells");
  return {cmd, [request, method] {
            request->method = *vision::ParseSegmentationMethod(*method);
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
