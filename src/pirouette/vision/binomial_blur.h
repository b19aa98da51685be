#pragma once

#include <opencv2/core.hpp>

namespace pirouette::vision {

// The even order n of the binomial kernel C(n, k) / 2^n (n + 1 taps) whose
// variance n / 4 is nearest sigma²: a Gaussian low-pass of `sigma` pixels in
// integer taps (sigma 1 → [1 4 6 4 1] / 16, 0.7 → [1 2 1] / 4, exactly σ 0.71).
// 0 (no low-pass) for sigma <= 0. By the central limit theorem the binomial
// kernel is the discrete Gaussian of its variance, and needs no multiplies
// beyond small constants: the cheap low-pass of Burt & Adelson's pyramids.
int BinomialOrder(double sigma);

// `src` (8-bit, 1 or 3 interleaved channels) low-passed by the binomial kernel
// of `order` (even, >= 0) along both axes, each channel on its own, rounded to
// nearest; borders reflected as OpenCV's default (BORDER_REFLECT_101). Order 0
// copies. Orders above 4 are applied as passes of at most 4 (rounded between).
// `dst` is (re)allocated to src's size and type unless it has them already,
// so that a caller that keeps it allocates once; it must not alias `src`.
void BinomialBlur(const cv::Mat& src, cv::Mat& dst, int order);

}  // namespace pirouette::vision
