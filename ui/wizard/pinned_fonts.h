#pragma once
// Pages and work orders rendered to images must look the same on every
// Debian machine: the screenshot goldens compare them pixel by pixel, and
// `auvballast-gui --render-pages` shows a newcomer what the tests see. Which
// fonts fontconfig finds depends on what else happens to be installed (a
// missing DejaVu Sans Oblique is synthesised; a glyph absent from DejaVu is
// taken from whatever font has it), so rendering is pinned to Debian's
// DejaVu folder (packages fonts-dejavu-core and fonts-dejavu-extra, see
// scripts/setup-deps.sh) and to the Fusion style at DejaVu Sans 10 pt.
#include <QString>

namespace auv::ui {

// The folder and the files the pinned rendering needs.
inline constexpr const char* kDejaVuDir = "/usr/share/fonts/truetype/dejavu";

// Call before the QApplication exists: writes a fontconfig file into
// `scratch_dir` that sees only kDejaVuDir (plus Debian's rendering rules in
// /etc/fonts/conf.d) and points FONTCONFIG_FILE at it. Returns an empty
// string on success, else what is missing and how to install it.
QString pinFontsToDejaVu(const QString& scratch_dir);

// Call after the QApplication exists: Fusion style, DejaVu Sans 10 pt, no
// cursor blinking (a blinking cursor makes screenshots random).
void pinRenderingLook();

}  // namespace auv::ui
