"""Prints how rtshell reads each `cwd<TAB>path` line of stdin: resolved against RTCSH_CWD by its
commands' helper, then split by rtctree. One line each: `ok<TAB>[:port]<TAB>bits...` or
`error<TAB>exception`."""
import os
import sys

import rtctree.path
import rtshell.path

for line in sys.stdin:
    cwd, path = line.rstrip('\n').split('\t')
    os.environ[rtshell.path.ENV_VAR] = cwd
    try:
        bits, port = rtctree.path.parse_path(rtshell.path.cmd_path_to_full_path(path))
        print('ok', '' if port is None else ':' + port, *bits, sep='\t')
    except Exception as e:
        print('error', type(e).__name__, sep='\t')
