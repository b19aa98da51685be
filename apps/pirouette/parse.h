#pragma once

#include <string>
#include <vector>

#include "pirouette/core/pose2.h"

namespace pirouette::cli {

// Parses "A,B,C,..." into exactly `count` numbers; throws core::InputError
// naming `option` otherwise.
std::vector<double> ParseNumbers(const std::string& text, std::size_t count,
                                 const std::string& option, const std::string& meaning);

// Parses "X,Y,HEADING" (metres, metres, degrees) into a pose.
core::Pose2 ParsePose(const std::string& text, const std::string& option);

}  // namespace pirouette::cli
