#!/usr/bin/env bash
# Installs the peer tools the tests run against (omniNames, omniidl, rtshell, rtctree) into a virtual
# environment outside the repository, once; later runs only check it. Prints where they are.
#
#   RTCOORD_PEERS   the virtual environment (default: ${XDG_CACHE_HOME:-~/.cache}/rtcoord/peers)
set -euo pipefail

requirements="$(cd "$(dirname "$0")" && pwd)/peers-requirements.txt"
venv="${RTCOORD_PEERS:-${XDG_CACHE_HOME:-$HOME/.cache}/rtcoord/peers}"
stamp="$venv/.rtcoord-requirements"

if [ -x "$venv/bin/python" ] && cmp -s "$requirements" "$stamp"; then
  echo "peers: up to date in $venv"
else
  echo "peers: installing into $venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --disable-pip-version-check --quiet -r "$requirements"
  cp "$requirements" "$stamp"
fi

for tool in omniNames nameclt catior omniidl rtls rtcat rtact rtcon rtconf rtwatch; do
  [ -x "$venv/bin/$tool" ] || { echo "peers: $tool is missing from $venv/bin" >&2; exit 1; }
done
echo "peers: tools in $venv/bin (tests find them through RTCOORD_PEERS=$venv)"
