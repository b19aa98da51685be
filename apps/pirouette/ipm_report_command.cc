#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/tools/ipm_report.h"

namespace pirouette::cli {

Command AddIpmReportCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::IpmReportRequest>();
  CLI::App* cmd = parent.add_subcommand(
      "ipm-report",
      "Print how far 1 pixel of floor-edge error moves the floor point, by range, for a camera, "
      "and the maximum range where it stays under half a map cell (the paper's rule).\n  "
      "example: pirouette ipm-report --camera worlds/yujin.yaml");
  AddCameraOption(cmd, request->camera_path)->required();
  AddCellOption(cmd, request->cell_m);
  cmd->add_option("--step", request->step_m, "the table's range step, metres")
      ->capture_default_str();
  cmd->add_flag("--json", request->json, "print JSON instead of a table");
  return {cmd, [request] { std::fputs(tools::IpmReport(*request).c_str(), stdout); }};
}

}  // namespace pirouette::cli
