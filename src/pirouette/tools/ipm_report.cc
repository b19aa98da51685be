#include "pirouette/tools/ipm_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/tools/json_output.h"

namespace pirouette::tools {
namespace {

std::string IpmReportJson(const camera::CameraModel& camera, double cell_m, double max_range_m,
                          const std::optional<camera::RangeInterval>& measurable,
                          const std::vector<camera::RangeError>& table) {
  nlohmann::ordered_json json;
  json["camera"] = camera.name();
  json["column"] = camera.intrinsics().cx;
  json["cell_m"] = cell_m;
  json["max_range_m"] = RoundTo(max_range_m, 4);
  if (measurable) {
    json["measurable_m"] = {RoundTo(measurable->near_m, 4), RoundTo(measurable->far_m, 4)};
  }
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const camera::RangeError& e : table) {
    rows.push_back({{"range_m", RoundTo(e.range_m, 3)},
                    {"row", RoundTo(e.row, 2)},
                    {"nearer_m", RoundTo(e.nearer_m, 5)},
                    {"farther_m", RoundTo(e.farther_m, 5)}});
  }
  json["table"] = std::move(rows);
  return JsonText(json, 2);
}

}  // namespace

std::string IpmReport(const IpmReportRequest& request) {
  if (!(request.cell_m > 0.0) || !std::isfinite(request.cell_m)) {
    throw core::InputError("--cell", 0, "", "the cell size must be a number > 0 (metres)");
  }
  if (!(request.step_m > 0.0) || !std::isfinite(request.step_m)) {
    throw core::InputError("--step", 0, "", "the step must be a number > 0 (metres)");
  }
  const camera::CameraModel camera = io::LoadCameraFile(request.camera_path);
  const double max_range = camera::MaxRange(camera, request.cell_m);
  const std::optional<camera::RangeInterval> measurable = camera::MeasurableRanges(camera);
  const std::vector<camera::RangeError> table =
      camera::RangeErrorTable(camera, request.step_m, std::max(1.0, 2.0 * max_range));
  if (request.json) return IpmReportJson(camera, request.cell_m, max_range, measurable, table);
  std::string out;
  out += fmt::format(
      "camera {}: {}x{} px, fy {:.1f} px, {:.3f} m above the floor, tilted {:.1f} deg down, "
      "{:.3f} m ahead of the centre\n",
      camera.name(), camera.width(), camera.height(), camera.intrinsics().fy,
      camera.mount().height_m, core::RadToDeg(camera.mount().tilt_rad), camera.mount().forward_m);
  out += fmt::format(
      "How far the floor point moves for 1 pixel of boundary error, along the image column "
      "straight ahead (u = {}):\nnearer: the edge read 1 pixel lower; farther: 1 pixel "
      "higher\n",
      camera.intrinsics().cx);
  out += fmt::format("{:>9} {:>8} {:>12} {:>12}\n", "range_m", "row_px", "nearer_cm", "farther_cm");
  for (const camera::RangeError& e : table) {
    out += fmt::format("{:>9.3f} {:>8.2f} {:>12.3f} {:>12.3f}{}\n", e.range_m, e.row,
                       100.0 * e.nearer_m, 100.0 * e.farther_m,
                       e.worst_m() < 0.5 * request.cell_m ? "" : "  > half a cell");
  }
  if (measurable) {
    out += fmt::format("the column sees the floor from {:.3f} m to {:.3f} m\n", measurable->near_m,
                       measurable->far_m);
  }
  out += fmt::format(
      "max range: {:.3f} m (up to there 1 pixel moves the point by less than half a {:.1f} cm "
      "cell)\n",
      max_range, 100.0 * request.cell_m);
  return out;
}

}  // namespace pirouette::tools
