// Fuzzes the camera file (SPEC.md; io/camera_file.h), every distortion
// model: the input is the file. Only core::InputError answers a bad file; a
// camera that loads must take the model's calls at its corners and centre
// and write a text that loads back. The same bytes go to LoadCameraMount.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>

#include <Eigen/Core>

#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/testing/fuzz_input.h"

namespace pirouette::io {
namespace {

void Exercise(const camera::CameraModel& camera) {
  const double w = camera.width() - 1.0;
  const double h = camera.height() - 1.0;
  for (const Eigen::Vector2d& pixel : {Eigen::Vector2d(0, 0), Eigen::Vector2d(w, h),
                                       Eigen::Vector2d(w / 2, h / 2), Eigen::Vector2d(0, h)}) {
    (void)camera.Backproject(pixel);
    (void)camera.FloorPoint(pixel);
    (void)camera.VignettingGain(0, pixel);
  }
}

}  // namespace
}  // namespace pirouette::io

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pirouette::testing::FuzzFolder folder;
  folder.Reset();
  const std::string path = folder.Write("camera.yaml", pirouette::testing::FuzzText(data, size));
  std::optional<pirouette::camera::CameraModel> camera;
  try {
    camera = pirouette::io::LoadCameraFile(path);
  } catch (const pirouette::core::InputError&) {
  }
  if (camera) {
    pirouette::io::Exercise(*camera);
    // What CameraFileText writes must load (an InputError here escapes).
    const std::string again = folder.Write("again.yaml", pirouette::io::CameraFileText(*camera));
    const pirouette::camera::CameraModel reread = pirouette::io::LoadCameraFile(again);
    if (reread.width() != camera->width() || reread.height() != camera->height()) std::abort();
  }
  try {
    (void)pirouette::io::LoadCameraMount(path);
  } catch (const pirouette::core::InputError&) {
  }
  return 0;
}
