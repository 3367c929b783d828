#include "golden.h"

#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <cstdlib>

namespace auv::testing {

ImageDiff compareImages(const QImage& actual, const QImage& expected, int channel_tolerance) {
  ImageDiff d;
  if (actual.size() != expected.size() || actual.isNull()) return d;
  d.same_size = true;
  const QImage a = actual.convertToFormat(QImage::Format_RGB32);
  const QImage e = expected.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < a.height(); ++y) {
    const QRgb* la = reinterpret_cast<const QRgb*>(a.constScanLine(y));
    const QRgb* le = reinterpret_cast<const QRgb*>(e.constScanLine(y));
    for (int x = 0; x < a.width(); ++x) {
      const int diff = std::max({std::abs(qRed(la[x]) - qRed(le[x])), std::abs(qGreen(la[x]) - qGreen(le[x])),
                                 std::abs(qBlue(la[x]) - qBlue(le[x]))});
      d.max_channel_diff = std::max(d.max_channel_diff, diff);
      if (diff > channel_tolerance) ++d.differing;
    }
  }
  d.fraction = static_cast<double>(d.differing) / (static_cast<double>(a.width()) * a.height());
  return d;
}

QString checkGolden(const QImage& img, const QString& name, GoldenTolerance tol) {
  const QString golden = QString(AUV_GOLDEN_DIR) + "/" + name + ".png";
  if (qEnvironmentVariable("AUV_BLESS_GOLDENS") == "1") {
    QDir().mkpath(AUV_GOLDEN_DIR);
    return img.save(golden) ? QString() : QString("cannot write %1").arg(golden);
  }
  const QImage expected(golden);
  if (expected.isNull()) return QString("no golden %1; run scripts/bless-goldens.sh after checking the screenshot").arg(golden);
  const ImageDiff d = compareImages(img, expected, tol.channel);
  if (!d.same_size) {
    img.save(QString(AUV_SCREENSHOT_DIR) + "/" + name + ".actual.png");
    return QString("%1: size %2x%3, golden %4x%5").arg(name).arg(img.width()).arg(img.height())
        .arg(expected.width()).arg(expected.height());
  }
  if (d.fraction <= tol.max_fraction) return QString();
  // Keep the evidence: the actual image and the differing pixels in red.
  QDir().mkpath(AUV_SCREENSHOT_DIR);
  img.save(QString(AUV_SCREENSHOT_DIR) + "/" + name + ".actual.png");
  QImage diff = expected.convertToFormat(QImage::Format_RGB32);
  const QImage a = img.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < diff.height(); ++y) {
    QRgb* ld = reinterpret_cast<QRgb*>(diff.scanLine(y));
    const QRgb* la = reinterpret_cast<const QRgb*>(a.constScanLine(y));
    for (int x = 0; x < diff.width(); ++x) {
      const int dd = std::max({std::abs(qRed(la[x]) - qRed(ld[x])), std::abs(qGreen(la[x]) - qGreen(ld[x])),
                               std::abs(qBlue(la[x]) - qBlue(ld[x]))});
      ld[x] = dd > tol.channel ? qRgb(255, 0, 0) : qRgb(qGray(ld[x]) / 2 + 128, qGray(ld[x]) / 2 + 128, qGray(ld[x]) / 2 + 128);
    }
  }
  diff.save(QString(AUV_SCREENSHOT_DIR) + "/" + name + ".diff.png");
  return QString("%1: %2 px (%3 %) of the pixels differ by more than %4 (allowed %5 %); see %6.diff.png")
      .arg(name)
      .arg(d.differing)
      .arg(d.fraction * 100, 0, 'f', 4)
      .arg(tol.channel)
      .arg(tol.max_fraction * 100, 0, 'f', 4)
      .arg(QString(AUV_SCREENSHOT_DIR) + "/" + name);
}

}  // namespace auv::testing
