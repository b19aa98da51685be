#pragma once

#include <atomic>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/app/exploration.h"

namespace pirouette::app {

// What `pirouette explore` was asked.
struct ExploreRequest {
  std::string world_path;
  std::string out_dir = "out";
  ExplorationOptions options;
  bool video = false;
  bool quiet = false;
};

// What it made.
struct ExploreReport {
  ExplorationResult result;
  nlohmann::json run;  // run.json's content
};

// Explores the world of the request and writes, atomically, OUT/map.yaml,
// OUT/map.pgm, OUT/map.png, OUT/run.json (SPEC.md) and with `video`
// OUT/explore.mp4; the outputs are written whatever the status, so an
// interrupted or stuck run keeps its map. Progress goes to standard error
// unless `quiet`. Throws core::InputError for a bad world or option.
ExploreReport RunExplore(const ExploreRequest& request);

// run.json (SPEC.md's `pirouette-run/1`) for a result; `eval` is the map's
// evaluation object.
nlohmann::json RunJson(const ExploreRequest& request, const ExplorationResult& result,
                       const nlohmann::json& eval);

}  // namespace pirouette::app
