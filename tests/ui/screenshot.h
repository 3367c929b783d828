#pragma once
// Renders a widget to <build>/screenshots/<name>.png and returns the image,
// so tests can assert on pixels and people can look at the result;
// `shot` also compares it with the committed golden (golden.h).
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QPixmap>
#include <QWidget>

#include "golden.h"

namespace auv::testing {

inline QImage screenshot(QWidget& w, const QString& name) {
  w.show();
  QApplication::processEvents();
  const QImage img = w.grab().toImage();
  QDir().mkpath(AUV_SCREENSHOT_DIR);
  img.save(QString(AUV_SCREENSHOT_DIR) + "/" + name + ".png");
  return img;
}

inline QImage shot(QWidget& w, const QString& name, GoldenTolerance tol = {}) {
  const QImage img = screenshot(w, name);
  const QString problem = checkGolden(img, name, tol);
  EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
  return img;
}

// Fraction of pixels close to the given colour (per channel within tol).
inline double colourFraction(const QImage& img, QColor c, int tol = 30) {
  long hit = 0;
  const QImage rgb = img.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < rgb.height(); ++y) {
    const QRgb* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
    for (int x = 0; x < rgb.width(); ++x) {
      if (std::abs(qRed(line[x]) - c.red()) <= tol && std::abs(qGreen(line[x]) - c.green()) <= tol &&
          std::abs(qBlue(line[x]) - c.blue()) <= tol)
        ++hit;
    }
  }
  return static_cast<double>(hit) / (rgb.width() * rgb.height());
}

}  // namespace auv::testing
