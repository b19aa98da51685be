#pragma once

#include <string>

namespace pirouette::tools {

struct IpmReportRequest {
  std::string camera_path;  // a camera file (SPEC.md)
  double cell_m = 0.01;     // the map cell the maximum range is derived for
  double step_m = 0.05;     // the table's range step
  bool json = false;
};

// `pirouette ipm-report`: how far ±1 pixel of boundary error along the image
// column straight ahead moves the floor point, by range (to twice the
// maximum range, at least 1 m, at most as far as the column sees), and the maximum
// range by the paper's rule (camera::MaxRange), as a text table or as JSON.
// Returns the text to print. Throws core::InputError for a bad camera file or
// a cell or step that is not > 0.
std::string IpmReport(const IpmReportRequest& request);

}  // namespace pirouette::tools
