#include "wizard/pinned_fonts.h"

#include <QApplication>
#include <QFont>
#include <QStyleFactory>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace auv::ui {

QString pinFontsToDejaVu(const QString& scratch_dir) {
  namespace fs = std::filesystem;
  // Regular and bold from fonts-dejavu-core; the obliques (italic text on
  // the pages) only from fonts-dejavu-extra.
  for (const char* f : {"DejaVuSans.ttf", "DejaVuSans-Bold.ttf", "DejaVuSans-Oblique.ttf", "DejaVuSans-BoldOblique.ttf",
                        "DejaVuSansMono.ttf"}) {
    if (!fs::exists(fs::path(kDejaVuDir) / f)) {
      return QString("%1/%2 is missing: install the Debian packages fonts-dejavu-core and fonts-dejavu-extra "
                     "(scripts/setup-deps.sh)")
          .arg(kDejaVuDir, f);
    }
  }
  const fs::path dir = fs::path(scratch_dir.toStdString());
  std::error_code ec;
  fs::create_directories(dir / "fontconfig-cache", ec);
  // Written beside and renamed into place: processes started together (ctest
  // -j) share the folder and must never read a half-written file.
  const fs::path conf = dir / "fonts.conf";
  const fs::path part = dir / ("fonts.conf." + std::to_string(getpid()));
  std::ofstream out(part, std::ios::trunc);
  out << "<?xml version=\"1.0\"?>\n<!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">\n<fontconfig>\n"
      << "  <dir>" << kDejaVuDir << "</dir>\n"
      << "  <cachedir>" << (dir / "fontconfig-cache").string() << "</cachedir>\n"
      << "  <include ignore_missing=\"yes\">/etc/fonts/conf.d</include>\n"
      << "</fontconfig>\n";
  out.close();
  fs::rename(part, conf, ec);
  if (!out || ec) return QString("cannot write %1: check the folder").arg(QString::fromStdString(conf.string()));
  setenv("FONTCONFIG_FILE", conf.c_str(), 1);
  return {};
}

void pinRenderingLook() {
  QApplication::setStyle(QStyleFactory::create("Fusion"));
  QApplication::setFont(QFont("DejaVu Sans", 10));
  QApplication::setCursorFlashTime(0);
}

}  // namespace auv::ui
