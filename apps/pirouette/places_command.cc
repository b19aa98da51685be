#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/tools/places.h"

namespace pirouette::cli {

Command AddPlacesCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::PlacesRequest>();
  auto method = std::make_shared<std::string>("default");
  auto spacing = std::make_shared<double>(0.0);
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = parent.add_subcommand(
      "places",
      "Measure place recognition from the Radial Obstacle Profile (Taylor, Geva & Boles 2005, "
      "§5.1 and §5.3): build a table of places by simulating a pirouette at grid poses (or load "
      "it with --table), then make pirouettes at random poses and headings and report, for each "
      "signature (dct: the paper's first 20 DCT coefficients; hu: Hu moments; fourier: the "
      "heading-invariant |FFT| with the heading by cross-correlation; colour: |FFT| and colour "
      "classes of what was hit), how often the best match is the right place (within one coarse "
      "cell of the nearest table place) and the heading is within 10 degrees. Progress on "
      "standard error, the table on standard output.\n  example: pirouette places --world "
      "worlds/soccer_field.yaml --queries 100 --seed 1 --table soccer_places.yaml --out "
      "places.json");
  AddWorldOption(cmd, request->world_path)->required();
  cmd->add_option("--queries", request->queries, "random poses to query")->capture_default_str();
  AddSeedOption(cmd, request->seed, "the random poses and the simulator's noise");
  AddPlaceTableOption(cmd, request->table_path,
                      "loaded if it exists, else built and written there");
  CLI::Option* spacing_option = cmd->add_option(
      "--spacing", *spacing,
      "the table grid's spacing, metres (default: the coarse cell, at least 4 robot radii)");
  AddMethodOption(cmd, *method, kMaskSources);
  AddRangeFactorOption(cmd, request->range_factor);
  AddReportOption(cmd, *out);
  auto no_refine = std::make_shared<bool>(false);
  cmd->add_flag("--no-refine", *no_refine,
                "judge the heading-giving signatures' matched places as they are, without "
                "refining the position and heading by aligning the two profiles");
  AddQuietOption(cmd, request->quiet);
  return {cmd, [request, method, spacing, spacing_option, out, no_refine] {
            request->refine = !*no_refine;
            request->method = *vision::ParseMaskSource(*method);
            if (spacing_option->count() > 0) request->spacing_m = *spacing;
            const tools::PlacesResult result = tools::MeasurePlaces(*request);
            std::printf(
                "places in %s: %d table places (spacing %.3f m%s), %d queries, coarse "
                "cell %.3f m\n",
                result.world_name.c_str(), result.table_places, result.spacing_m,
                result.table_loaded ? ", loaded" : "", result.queries, result.coarse_cell_m);
            std::printf("%-9s %7s %9s %14s   %s\n", "signature", "place", "heading", "mean err deg",
                        "informative queries: place, heading");
            const double n = result.queries;
            const double k = std::max(1, result.informative_queries);
            for (const tools::SignatureScore& s : result.scores) {
              const std::string name(localize::SignatureKindName(s.kind));
              if (localize::SignatureGivesHeading(s.kind)) {
                std::printf("%-9s %6.1f%% %8.1f%% %14.1f   %6.1f%% %6.1f%%\n", name.c_str(),
                            100.0 * s.place_hits / n, 100.0 * s.heading_hits / n,
                            s.mean_heading_error_deg, 100.0 * s.informative_place_hits / k,
                            100.0 * s.informative_heading_hits / k);
              } else {
                std::printf("%-9s %6.1f%% %9s %14s   %6.1f%% %7s\n", name.c_str(),
                            100.0 * s.place_hits / n, "-", "-",
                            100.0 * s.informative_place_hits / k, "-");
              }
            }
            std::printf("informative queries (>= %d of 360 bearings hit something): %d of %d\n",
                        tools::kInformativeBins, result.informative_queries, result.queries);
            if (!out->empty()) {
              io::WriteFileAtomically(*out, tools::PlacesJson(*request, result).dump(2) + "\n");
              std::fprintf(stderr, "wrote %s\n", out->c_str());
            }
          }};
}

}  // namespace pirouette::cli
