#include "pirouette/tools/segment_eval.h"

#include <nlohmann/json.hpp>

#include "pirouette/tools/json_output.h"

namespace pirouette::tools {

std::string SegmentationEvalJson(const eval::SegmentationEvalRequest& request,
                                 const eval::SegmentationEvalResult& result) {
  nlohmann::ordered_json json;
  json["method"] = std::string(vision::SegmentationMethodName(request.method));
  json["first"] = request.first;
  json["last"] = request.last;
  json["mean_iou"] = RoundTo(result.mean_iou, 4);
  if (result.boundary_error_median_px && result.boundary_error_p95_px) {
    json["boundary_error_median_px"] = RoundTo(*result.boundary_error_median_px, 1);
    json["boundary_error_p95_px"] = RoundTo(*result.boundary_error_p95_px, 1);
  }
  if (result.boundary_bias_median_px) {
    json["boundary_bias_median_px"] = RoundTo(*result.boundary_bias_median_px, 1);
  }
  nlohmann::ordered_json images = nlohmann::ordered_json::array();
  for (const eval::ImageScore& s : result.images) {
    images.push_back({{"index", s.index},
                      {"iou", RoundTo(s.iou, 4)},
                      {"precision", RoundTo(s.precision, 4)},
                      {"recall", RoundTo(s.recall, 4)}});
  }
  json["images"] = std::move(images);
  return JsonText(json, 2);
}

}  // namespace pirouette::tools
