#pragma once
// Golden-image comparison for page screenshots. Two images match when they
// have the same size and at most `max_fraction` of the pixels differ by more
// than `channel_tolerance` in any of R, G, B. The tolerance absorbs
// anti-aliasing noise; the fraction lets a moved text baseline through but
// not a changed number, a missing chart line or a different layout.
#include <QImage>
#include <QString>

namespace auv::testing {

struct ImageDiff {
  bool same_size = false;
  long differing = 0;       // pixels with a channel off by more than the tolerance
  double fraction = 1.0;    // differing / all pixels
  int max_channel_diff = 0;
};

ImageDiff compareImages(const QImage& actual, const QImage& expected, int channel_tolerance);

// Rendering offscreen with a pinned style and font is deterministic on one
// platform build, so the tolerance is tight: 24/255 per channel absorbs
// blending differences between CPUs, and 0.002 % of the pixels (15 px of a
// 1000 x 760 page) is less than half of one changed digit (~40 px, see
// golden_test.cpp). Identical runs differ in 0 px.
struct GoldenTolerance {
  int channel = 24;
  double max_fraction = 0.00002;
};

// Compares `img` with tests/ui/golden/<name>.png. With AUV_BLESS_GOLDENS=1 in
// the environment the golden is (re)written instead (scripts/bless-goldens.sh).
// On a mismatch the actual image and a diff image are written next to the
// screenshots (<name>.actual.png, <name>.diff.png) for a person to look at.
// Returns an empty string on success, else what was wrong.
QString checkGolden(const QImage& img, const QString& name, GoldenTolerance tol = {});

}  // namespace auv::testing
