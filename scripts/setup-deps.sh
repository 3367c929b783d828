#!/usr/bin/env bash
# Installs the Debian 12 packages auvballast builds and is tested with.
# Idempotent; needs root. The fonts are part of the test set-up: the
# screenshot goldens are rendered with DejaVu Sans only (fonts-dejavu-core
# has regular and bold, fonts-dejavu-extra the oblique of italic text; see
# ui/wizard/pinned_fonts.h). help2man makes the man pages at build time;
# lintian and appstream check the .deb (packaging/check-package.sh).
set -euo pipefail
PKGS=(build-essential cmake ninja-build file pkg-config git
      qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-svg-dev libqt6sql6-sqlite
      qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
      libeigen3-dev nlohmann-json3-dev libcli11-dev libsqlite3-dev libnetcdf-dev zlib1g-dev liblz4-dev
      libgtest-dev libgmock-dev libbenchmark-dev
      libgl1-mesa-dev libxkbcommon-dev fonts-dejavu-core fonts-dejavu-extra
      help2man lintian appstream
      clang libclang-rt-14-dev)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
