#pragma once

#include <optional>
#include <string_view>

namespace pirouette::vision {

// Where a run's floor masks come from: one of vision's segmenters (the
// paper's, or the default appearance model), or the truth, which only the
// simulator knows (its ray caster's mask, to measure the profile extraction
// alone).
enum class MaskSource { kPaper, kDefault, kTruth };

// "paper" | "default" | "truth"; nullopt for any other name.
std::optional<MaskSource> ParseMaskSource(std::string_view name);
std::string_view MaskSourceName(MaskSource source);

}  // namespace pirouette::vision
