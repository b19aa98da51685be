#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "pirouette/core/colour_class.h"

namespace pirouette::localize {

// What a robot sees of a place from one pirouette: its Radial Obstacle
// Profile (mapping::RadialProfile, kRadialProfileBins one-degree bins) in the
// robot's own frame (bin b: bearings [b, b + 1)° counter-clockwise from the
// robot's heading at the pirouette's start), and the colour class of what
// each bearing hit (Taylor, Geva & Boles 2005, §5.1's colour ROP).
struct PlaceView {
  std::vector<double> ranges_m;            // kRadialProfileBins, each in [0, max range]
  std::vector<core::ColourClass> colours;  // kRadialProfileBins, or empty (no colour)
};

// The signatures of a place that `pirouette places` measures.
enum class SignatureKind {
  kDct,      // the paper's §5.3: the first 20 DCT coefficients; depends on heading
  kHu,       // Hu's 7 moment invariants of the ROP's polygon (§5.3: tried by the paper)
  kFourier,  // |FFT| of the ranges: heading-invariant; heading by cross-correlation
  kColour,   // |FFT| and a colour histogram, then range-and-colour alignment (§5.1)
};

inline constexpr std::array<SignatureKind, 4> kSignatureKinds = {
    SignatureKind::kDct, SignatureKind::kHu, SignatureKind::kFourier, SignatureKind::kColour};

// "dct" | "hu" | "fourier" | "colour".
std::string_view SignatureKindName(SignatureKind kind);
// Whether the signature recovers the query's heading relative to a match.
bool SignatureGivesHeading(SignatureKind kind);

// The DCT signature (Taylor, Geva & Boles 2005, §5.3): the first `keep`
// orthonormal DCT-II coefficients of the ranges (mapping::Dct). It changes
// with the robot's heading: a place is only recognised when the robot faces
// the way it did when the table was made.
inline constexpr int kDctSignatureLength = 20;
std::vector<double> DctSignature(const std::vector<double>& ranges_m,
                                 int keep = kDctSignatureLength);

// Hu's seven moment invariants (Hu 1962) of the ROP read as a closed polygon
// (vertex b at ranges_m[b]·(cos θ_b, sin θ_b), θ_b the bin's centre
// bearing), from the polygon's area moments up to order 3 by Green's theorem.
// Invariant to rotation (heading), and also to translation and scale, which
// is why the paper (§5.3) found them weak for places. Returned log-scaled,
// sign(h)·log10(|h|), 0 where |h| < 1e-30, as they are compared.
using HuSignature = std::array<double, 7>;
HuSignature HuMoments(const std::vector<double>& ranges_m);
// The raw (not log-scaled) invariants, for tests.
std::array<double, 7> RawHuMoments(const std::vector<double>& ranges_m);

// The heading-invariant Fourier signature: |X_k| / N for k = 0 … keep − 1 of
// the ranges' DFT X (N bins). A turn of the robot shifts the ROP circularly,
// which changes only the phases: the magnitudes name the place whatever the
// heading (an alternative to §5.3's DCT, which is not heading-invariant).
inline constexpr int kFourierSignatureLength = 20;
std::vector<double> FourierSignature(const std::vector<double>& ranges_m,
                                     int keep = kFourierSignatureLength);

// The colour signature (§5.1's colour ROP): the Fourier signature of the
// ranges and the fraction of the bearings that hit each colour class
// (kColourClasses of them, kNone left out), both heading-invariant.
struct ColourSignature {
  std::vector<double> fourier;
  std::array<double, core::kColourClasses> histogram{};
};
ColourSignature MakeColourSignature(const PlaceView& view);

// Euclidean distances between signatures of the same length (metres for the
// DCT and Fourier signatures).
double SignatureDistance(const std::vector<double>& a, const std::vector<double>& b);
// The L1 distance between log-scaled Hu moments (OpenCV's CONTOURS_MATCH_I1-like).
double HuDistance(const HuSignature& a, const HuSignature& b);
// The Fourier distance (metres) plus kColourHistogramWeight × the colour
// histograms' L1 distance (of 2) times the larger profile mean.
inline constexpr double kColourHistogramWeight = 0.5;
double ColourSignatureDistance(const ColourSignature& a, const ColourSignature& b);

// How a query's profile lines up with a reference's.
struct Alignment {
  // The query robot's heading in the reference's frame, radians in (−π, π]:
  // query bin b looks where reference bin b + heading (in degrees) looks.
  double heading_rad = 0.0;
  // The alignment's cost at that heading: the mean squared range difference
  // over the squared max range, plus (with colours) kColourMismatchWeight ×
  // the fraction of bins, among those both coloured, whose classes disagree: a
  // hue against black, white or grey, or hues more than one class (30°)
  // apart. Black, white and grey agree with each other, as light and shading
  // move a white wall between them.
  double cost = 0.0;
};

inline constexpr double kColourMismatchWeight = 0.2;

// The best circular shift of the query's ranges against the reference's
// (circular cross-correlation by brute force over the 360 one-degree shifts,
// the minimum of the mean squared difference), refined below a bin by a
// parabola through the best cost and its neighbours. With `use_colour` and
// both views coloured, the colour classes' disagreement joins the cost, so
// that a room whose ranges repeat under rotation (a symmetric room) is told
// apart by the colours of what stands in it. Throws std::invalid_argument
// unless the views have the same number of bins, at least one.
Alignment AlignProfiles(const PlaceView& query, const PlaceView& reference, bool use_colour);

// `view` (a pirouette's ROP in its robot's frame) as it would look from
// `origin_m` in that frame, heading unchanged: every bin that hit something
// (range below max_range_m) is a point on the floor; each point falls in the
// bin of its bearing from the origin, the nearest point a bin winning (with
// its colour). Empty bins between filled ones at most kReprojectGapBins apart
// are interpolated; the rest read max_range_m (clear) with no colour. An
// approximation: what the view did not see (behind obstacles, past the max
// range) stays unseen.
inline constexpr int kReprojectGapBins = 4;
PlaceView Reproject(const PlaceView& view, const Eigen::Vector2d& origin_m, double max_range_m);

// A query's pose in a reference view's frame.
struct PoseAlignment {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // the query robot's centre
  double heading_rad = 0.0;
  double cost = 0.0;  // AlignProfiles's cost there
};

// The query's pose relative to a reference pirouette made nearby: the
// position o within search_radius_m of the reference's centre (coarse to
// fine, from a 5 × 5 grid over the square of that half-side down to steps of
// min_step_m) where AlignProfiles(query, Reproject(reference, o)) costs
// least, with that alignment's heading. Where the reference was taken a few
// centimetres away, the parallax of near obstacles biases AlignProfiles's
// heading by tens of degrees; this removes it and gives the position too.
// (Taylor, Geva & Boles 2005, §5.3, leave heading and position within a
// place to future work; this is a small scan match of two ROPs.)
PoseAlignment AlignPose(const PlaceView& query, const PlaceView& reference, double max_range_m,
                        double search_radius_m, double min_step_m, bool use_colour);

}  // namespace pirouette::localize
