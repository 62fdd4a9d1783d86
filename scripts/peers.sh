#!/usr/bin/env bash
# Installs the peer tools the tests run against (omniNames, omniidl, rtshell, rtctree, Python's
# fluent-logger) into a virtual environment outside the repository, once; later runs only check it.
# Where npm is, Node.js's fluent-logger goes into its node/ folder too (the forward protocol's
# PackedForward, compression, acks and shared key, which the Python client does not send); the tests
# that need it are skipped without it. Prints where they are.
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

# Node.js's client is optional: the tests that need it say so when it is missing.
node_package="fluent-logger@3.4.1"
node_stamp="$venv/node/.rtcoord-package"
if command -v npm >/dev/null; then
  if [ "$(cat "$node_stamp" 2>/dev/null)" = "$node_package" ]; then
    echo "peers: $node_package up to date in $venv/node"
  else
    echo "peers: installing $node_package into $venv/node"
    npm install --prefix "$venv/node" --no-save --silent "$node_package"
    echo "$node_package" >"$node_stamp"
  fi
else
  echo "peers: npm is missing: the tests on Node.js's fluent-logger will be skipped"
fi

for tool in omniNames nameclt catior omniidl rtls rtcat rtact rtcon rtconf rtwatch; do
  [ -x "$venv/bin/$tool" ] || { echo "peers: $tool is missing from $venv/bin" >&2; exit 1; }
done
echo "peers: tools in $venv/bin (tests find them through RTCOORD_PEERS=$venv)"
