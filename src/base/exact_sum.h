// A running sum whose value does not depend on the order of its terms: the pair hi + lo of
// doubles, added to by Knuth's TwoSum, so that hi + lo holds the exact sum of the terms (106
// bits) where plain double addition rounds after every term.
//
// Why: the film adds each pixel's samples into such sums. A render split into sample ranges
// (or stopped and resumed) adds the same terms in other groupings, ((a + b) + c) + d against
// (a + b) + (c + d), which in plain doubles round differently; kept exact, the parts' sums
// merge into the very sum of the unsplit render, and the image, rounded from it once, is the
// same bit for bit.
//
// Exact when: every term is a product of two floats (48 significant bits, as the film's
// weight * value) or a float, and within one pixel the largest partial sum is at most about
// 2^58 / n times the smallest nonzero term (n terms): lo then collects the rounding errors of
// hi without rounding itself. Beyond that (a pixel whose samples span more than 2^40 in
// brightness at 2^16 samples) the sum is still correct to 1e-32 relative, and the images can
// differ only where that lands on a float's rounding boundary.
#pragma once

namespace objektiv {

struct ExactSum {
  double hi = 0, lo = 0;

  void Add(double x) {
    const double s = hi + x;
    const double b = s - hi;
    const double e = (hi - (s - b)) + (x - b);  // hi + x - s, exactly
    hi = s;
    lo += e;
  }
  void Add(const ExactSum& o) {
    Add(o.hi);
    lo += o.lo;
  }
  // The sum rounded once to a double: a function of the exact sum alone, however it was added.
  double Value() const { return hi + lo; }
  bool IsZero() const { return hi == 0 && lo == 0; }
};

}  // namespace objektiv
