"""Attaches rtctree's own ComponentObserver (the OMG flavour rtwatch uses) to one component and prints
what it reports, one line per callback, until its standard input closes."""
import sys

from rtctree.tree import RTCTree

server, path = sys.argv[1], sys.argv[2:]
tree = RTCTree(servers=[server])
node = tree.get_node(['/', server] + path)
node.add_callback('rtc_status', lambda node, value, args: print('status', value[0], value[1], flush=True))
node.add_callback('heartbeat', lambda node, value, args: print('heartbeat', value[0], flush=True))
node.dynamic = True
print('attached', flush=True)
sys.stdin.readline()
node.dynamic = False
print('detached', flush=True)
