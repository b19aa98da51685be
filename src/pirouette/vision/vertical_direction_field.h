#pragma once

#include <opencv2/core.hpp>

#include "pirouette/camera/camera_model.h"

namespace pirouette::vision {

// For each raw pixel, the unit image direction (du, dv) in which a vertical
// line of the world through that pixel runs upward. In a tilted camera
// vertical edges of obstacles do not look vertical in the image, and lens
// distortion bends them further (Taylor, Geva & Boles 2005, §5.2); this field
// tells the segmenter, pixel by pixel, which edges are the vertical sides of
// obstacles. Built once from the camera model: the pixel's ray is followed to
// a point one metre from the optical centre, and the direction is that of the
// projections of two points 1 mm below and above it on the vertical line
// through it, with distortion. Pixels whose vertical line does not project
// (the line leaves the view at once) get the image's up direction (0, -1).
class VerticalDirectionField {
 public:
  explicit VerticalDirectionField(const camera::CameraModel& camera)
      : VerticalDirectionField(camera, 1) {}
  // For frames reduced by `scale` >= 1 (a pixel per scale × scale block of the
  // camera's, the partial blocks dropped): the direction at each block's centre.
  VerticalDirectionField(const camera::CameraModel& camera, int scale);
  // Without a camera: an upright pinhole, every vertical runs up the image.
  VerticalDirectionField(int width, int height);

  int width() const { return direction_.cols; }
  int height() const { return direction_.rows; }
  cv::Vec2f At(int u, int v) const { return direction_(v, u); }
  const cv::Mat2f& directions() const { return direction_; }

 private:
  cv::Mat2f direction_;
};

}  // namespace pirouette::vision
