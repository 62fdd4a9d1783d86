"""Attaches rtctree's own ComponentObserver (the OMG flavour rtwatch uses) to one component and prints
what it reports, one line per callback, until its standard input closes."""
import sys
import threading

from rtctree.tree import RTCTree

# omniORB runs callbacks on several threads: one line at a time, whole.
output = threading.Lock()


def say(*words):
    with output:
        sys.stdout.write(' '.join(str(word) for word in words) + '\n')
        sys.stdout.flush()


server, path = sys.argv[1], sys.argv[2:]
tree = RTCTree(servers=[server])
node = tree.get_node(['/', server] + path)
node.add_callback('rtc_status', lambda node, value, args: say('status', value[0], value[1]))
node.add_callback('heartbeat', lambda node, value, args: say('heartbeat', value[0]))
node.dynamic = True
say('attached')
sys.stdin.readline()
node.dynamic = False
say('detached')
