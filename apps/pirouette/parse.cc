#include "apps/pirouette/parse.h"

#include <charconv>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"

namespace pirouette::cli {

std::vector<double> ParseNumbers(const std::string& text, std::size_t count,
                                 const std::string& option, const std::string& meaning) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    double value = 0.0;
    const char* first = text.data() + start;
    const char* last = text.data() + comma;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || first == last) {
      throw core::InputError(option, 0, "", "expected " + meaning + ", got '" + text + "'");
    }
    values.push_back(value);
    start = comma + 1;
  }
  if (values.size() != count) {
    throw core::InputError(option, 0, "", "expected " + meaning + ", got '" + text + "'");
  }
  return values;
}

core::Pose2 ParsePose(const std::string& text, const std::string& option) {
  const auto v = ParseNumbers(text, 3, option, "X,Y,HEADING (metres, metres, degrees)");
  return {v[0], v[1], core::DegToRad(v[2])};
}

}  // namespace pirouette::cli
