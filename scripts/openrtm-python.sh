#!/usr/bin/env bash
# Builds an OpenRTM-aist-Python installation for the end-to-end tests on real OpenRTM-aist
# (examples' OpenRtmPythonTest) from a checkout of https://github.com/OpenRTM/OpenRTM-aist-Python,
# without its build backend (which fetches a build helper from GitHub): a virtual environment with
# omniORBpy, the OpenRTM_aist package, and its IDL compiled by omniidl; and fluent-logger, which OpenRTM's
# FluentLogger.py logger plugin imports to send a component's log records to rtcoord's log input.
#
#   scripts/openrtm-python.sh CHECKOUT [VENV]     VENV defaults to ~/.cache/rtcoord/openrtm-python
#
# Then: RTCOORD_OPENRTM_PYTHON=VENV/bin/python mvn -B -ntp verify -pl examples -am -Dtest=OpenRtmPythonTest
set -euo pipefail

checkout="${1:?usage: scripts/openrtm-python.sh CHECKOUT [VENV]}"
venv="${2:-${XDG_CACHE_HOME:-$HOME/.cache}/rtcoord/openrtm-python}"
[ -d "$checkout/OpenRTM_aist" ] || { echo "openrtm-python: $checkout has no OpenRTM_aist directory" >&2; exit 1; }

python3 -m venv "$venv"
requirements="$(dirname "$0")/peers-requirements.txt"
"$venv/bin/pip" install --disable-pip-version-check --quiet \
  "$(grep -i '^jeteve-omniorb' "$requirements")" "$(grep -i '^fluent-logger' "$requirements")"
site="$("$venv/bin/python" -c 'import site; print(site.getsitepackages()[0])')"
rm -rf "$site/OpenRTM_aist"
cp -r "$checkout/OpenRTM_aist" "$site/"
cp "$checkout/OpenRTM-aist.pth" "$site/"

# The stubs go where OpenRTM-aist.pth puts them on the path, the observers' with the rest.
cd "$site/OpenRTM_aist/RTM_IDL"
for idl in *.idl ../ext/sdo/observer/ComponentObserver_OpenRTM.idl ../ext/fsm4rtc_observer/ComponentObserver.idl; do
  "$venv/bin/omniidl" -bpython -I. -C. "$idl"
done
"$venv/bin/python" -c 'import OpenRTM_aist, RTC, OpenRTM, fluent.sender; OpenRTM.ComponentObserver' \
  || { echo "openrtm-python: the installation in $venv does not import" >&2; exit 1; }
echo "openrtm-python: RTCOORD_OPENRTM_PYTHON=$venv/bin/python"
