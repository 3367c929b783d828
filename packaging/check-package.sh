#!/usr/bin/env bash
# Checks the .deb built by cpack like a Debian desktop program
# (issue 14 item 12); scripts/test.sh runs it after cpack.
#   packaging/check-package.sh [build-dir]        (default: build)
# Fails when a file a Debian user expects is missing, the man page lacks a
# subcommand of --help, the AppStream file does not validate, or lintian
# reports an error. lintian and appstreamcli run when installed
# (scripts/setup-deps.sh installs both); their output goes to
# <build>/packages/lintian.txt and appstream.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
deb=$(ls "$build"/packages/auvballast_*.deb | head -n1)
fail() { echo "package check: $*" >&2; exit 1; }
contents=$(dpkg-deb -c "$deb" | awk '{print $NF}')
for f in ./usr/bin/auvballast ./usr/bin/auvballast-gui \
         ./usr/share/doc/auvballast/copyright ./usr/share/doc/auvballast/LICENSE ./usr/share/doc/auvballast/changelog.gz \
         ./usr/share/man/man1/auvballast.1.gz ./usr/share/man/man1/auvballast-gui.1.gz \
         ./usr/share/metainfo/io.github.auvballast.metainfo.xml ./usr/share/applications/auvballast.desktop \
         ./usr/share/icons/hicolor/scalable/apps/auvballast.svg ./usr/share/auvballast/resources/vehicles/hugin1000.json; do
  grep -qxF "$f" <<<"$contents" || fail "$f is not in $deb"
done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
dpkg-deb -x "$deb" "$tmp"
grep -q "^License: GPL-3+" "$tmp/usr/share/doc/auvballast/copyright" || fail "the copyright file does not state GPL-3+"
cmp -s LICENSE "$tmp/usr/share/doc/auvballast/LICENSE" || fail "the packaged LICENSE differs from ./LICENSE"
# The man page is made from --help at build time: every subcommand --help
# lists must be in it (a stale or empty page fails here).
man=$(zcat "$tmp/usr/share/man/man1/auvballast.1.gz" | sed 's/\\-/-/g')  # roff writes - as \-
subcommands=$("$build/app/cli/auvballast" --help | awk '/^Subcommands:/{on=1; next} on && NF {print $1}')
[ -n "$subcommands" ] || fail "auvballast --help lists no subcommands"
for c in $subcommands; do
  grep -qF -- "$c" <<<"$man" || fail "the man page lacks the subcommand $c: rebuild (help2man)"
done
grep -qF -- "--render-pages" <(zcat "$tmp/usr/share/man/man1/auvballast-gui.1.gz" | sed 's/\\-/-/g') || fail "the auvballast-gui man page lacks --render-pages"
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net "$tmp/usr/share/metainfo/io.github.auvballast.metainfo.xml" >"$build/packages/appstream.txt" 2>&1 ||
    { cat "$build/packages/appstream.txt"; fail "the AppStream metainfo does not validate"; }
  echo "package check: appstreamcli validate: ok"
else
  echo "package check: appstreamcli not installed, AppStream file not validated"
fi
if command -v lintian >/dev/null; then
  # lintian exits non-zero on an error tag (its default --fail-on error).
  lintian --display-info "$deb" >"$build/packages/lintian.txt" 2>&1 || { cat "$build/packages/lintian.txt"; fail "lintian found errors"; }
  echo "package check: lintian: $(grep -c '^E:' "$build/packages/lintian.txt" || true) errors, $(grep -c '^W:' "$build/packages/lintian.txt" || true) warnings (see $build/packages/lintian.txt)"
else
  echo "package check: lintian not installed, not run"
fi
echo "package check: ok ($deb)"
