# Times rtctree's RTCTree on a whole name server, in one warm Python process, the way rtshell's tools
# use it: constructing the tree parses every naming context and reads every component's profile.
# Then, for the same information rtcoord's snapshot holds, it reads every component's ports, execution
# contexts and states, which rtctree otherwise reads lazily.
#
# usage: python rtctree_discovery.py HOST:PORT WARMUPS REPETITIONS
# prints one line per repetition: "rep <construct seconds> <full seconds> <components>"
import sys
import time

from rtctree.tree import RTCTree


def read_everything(component, _):
    component.ports  # get_ports, then each port's profile
    component.owned_ecs  # owned contexts, each one's handle and profile
    component.participating_ecs
    component.owned_ec_states  # the state in each owned context
    return 1


def discover(address):
    start = time.perf_counter()
    tree = RTCTree(servers=address)
    constructed = time.perf_counter()
    components = sum(tree.iterate(read_everything, filter=['is_component']))
    done = time.perf_counter()
    # The tree destroys its ORB when it goes, as it would at the end of a tool's run.
    del tree
    return constructed - start, done - start, components


def main():
    address, warmups, repetitions = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    for _ in range(warmups):
        discover(address)
    for _ in range(repetitions):
        construct, full, components = discover(address)
        print("rep %.6f %.6f %d" % (construct, full, components), flush=True)


if __name__ == '__main__':
    main()
