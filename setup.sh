#!/usr/bin/env bash
# Install quasicentral and everything it needs on a fresh Debian machine with Python >= 3.11.
#   ./setup.sh          the library, its command and the LaTeX toolchain for the reports
#   ./setup.sh --test   the same, plus the test tools
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages: the LaTeX toolchain that `quasicentral report --pdf` compiles with, and
# poppler-utils (pdftoppm) that the report tests render pages with.
DEBS=(latexmk texlive-latex-base texlive-latex-recommended texlive-latex-extra texlive-fonts-recommended
      texlive-lang-czechslovak lmodern poppler-utils)
missing=()
for p in "${DEBS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

extra=""
[ "${1:-}" = "--test" ] && extra="[test]"
python3 -m pip install --quiet --disable-pip-version-check -e ".${extra}"
