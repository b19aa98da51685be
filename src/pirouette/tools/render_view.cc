#include "pirouette/tools/render_view.h"

#include <fmt/format.h>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/renderer.h"

namespace pirouette::tools {

void RenderView(const RenderViewRequest& request) {
  const sim::World world = io::LoadWorldFile(request.world_path);
  const Eigen::Vector2d p = request.world_T_robot.translation();
  if (!world.OnFloor(p)) {
    throw core::InputError(
        "--pose", 0, "",
        fmt::format("({:.3f}, {:.3f}) is off the floor of {} ([0, {}] x [0, {}])", p.x(), p.y(),
                    request.world_path, world.floor().size.x(), world.floor().size.y()));
  }
  sim::RenderOptions options;
  options.seed = request.seed;
  sim::Renderer renderer(world, world.robot().camera, options);
  io::WritePng(request.out_path, renderer.Render(request.world_T_robot));
}

}  // namespace pirouette::tools
