#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/image.h"
#include "pirouette/core/pose2.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

struct RenderOptions {
  // Standard deviation of the Gaussian sensor noise added to each channel, in 0–255 units.
  double noise_sigma = 2.0;
  // Seeds the sensor noise and the floor's texture.
  std::uint64_t seed = 1;
  // The camera turned by this angle about its optical axis, radians: the
  // camera's pose is robot_T_camera() times a rotation of roll_rad about the
  // camera frame's z. The camera model has no roll (a level mount);
  // calibration tests use it to vary the board's plane across views.
  double roll_rad = 0.0;
};

// There is no usable OpenGL (no EGL display, no context, a shader that does not compile).
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Renders what a World's camera sees, with real OpenGL through EGL, headless:
// the scene through an ideal pinhole, then the camera's lens distortion,
// vignetting and seeded sensor noise. See renderer.cc for the passes.
class Renderer {
 public:
  Renderer(const World& world, const camera::CameraModel& camera, const RenderOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The camera image with the robot at world_T_robot. The noise of frame k is
  // a function of (seed, k) only: the same calls give the same images.
  core::ImageRgb8 Render(const core::Pose2& world_T_robot);

  // The OpenGL renderer's name (e.g. "llvmpipe"), for messages and benchmarks.
  const std::string& gl_renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pirouette::sim
