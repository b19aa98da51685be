#include "pirouette/tools/rop.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/radial_profile_plot.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/simulated_pirouette.h"
#include "pirouette/vision/profile_extractor.h"
#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::tools {
namespace {

// The bin's centre bearing, radians.
double BinBearing(int bin) {
  return core::DegToRad((bin + 0.5) * 360.0 / mapping::kRadialProfileBins);
}

}  // namespace

RopResult MakeRop(const RopRequest& request) {
  const sim::World loaded = io::LoadWorldFile(request.world_path);
  const sim::World world = sim::PlaceRobot(loaded, request.world_T_robot, "--pose");
  const camera::CameraModel& camera = world.robot().camera;
  const double max_range = request.max_range_m.value_or(camera::MaxRange(camera, request.cell_m));
  if (!(max_range > 0.0) || !std::isfinite(max_range)) {
    throw core::InputError("--max-range", 0, "", "the max range must be a number > 0 (metres)");
  }
  sim::RenderOptions options;
  options.seed = request.seed;
  sim::Renderer renderer(world, camera, options);
  const std::vector<sim::SimulatedFrame> frames =
      sim::SimulatePirouette(world, renderer, request.seed);
  const camera::InversePerspectiveMap ipm(camera);
  const vision::VerticalDirectionField vertical(camera);
  eval::FloorMasker masker(request.method, world, camera);
  std::vector<mapping::HeadedProfile> views;
  for (const sim::SimulatedFrame& frame : frames) {
    const cv::Mat3b bgr = io::ToBgrMat(frame.frame.image);
    const cv::Mat1b mask = masker.Mask(bgr, frame.world_T_robot);
    views.push_back({frame.frame.odometry.heading(),
                     vision::ExtractProfile(mask, ipm, max_range, masker.Unresolved(), &vertical)});
  }
  RopResult result;
  result.rop = mapping::MergePirouette(views);
  result.low_pass = mapping::DctLowPass(result.rop.Ranges());
  // The odometry frame is the world frame at the pirouette's start.
  for (int b = 0; b < mapping::kRadialProfileBins; ++b) {
    const double bearing = BinBearing(b);
    const std::optional<double> hit = world.RayCast(
        request.world_T_robot.translation(), {std::cos(bearing), std::sin(bearing)}, max_range);
    result.truth.push_back(hit.value_or(max_range));
  }
  const std::string title = fmt::format(
      "{}  pose ({:.2f}, {:.2f}, {:.0f} deg)  method {}", world.name(), request.world_T_robot.x(),
      request.world_T_robot.y(), core::RadToDeg(request.world_T_robot.heading()),
      vision::MaskSourceName(request.method));
  io::WritePng(request.out_path,
               draw::PlotRadialProfile(result.rop, result.low_pass, result.truth, title));
  return result;
}

}  // namespace pirouette::tools
