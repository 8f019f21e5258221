#!/usr/bin/env python3
"""Replays a module's concurrent test run on its recorded class times (issue 38; docs/performance.md).

    scripts/replay-test-order.py MODULE [PARALLELISM]    e.g. scripts/replay-test-order.py ripv-it 3

Reads MODULE/target/class-times.txt (org.ripv.testing.ClassTimes: each class's own seconds) and the
@ResourceLock / @Isolated annotations of MODULE/src/test/java, and prints how long the module's
classes would take, each as long as it took in that run, when JUnit 5.11's fork-join executor runs
them PARALLELISM at a time in the order org.ripv.testing.LongestFirst gives, with
MODULE/src/test/resources/expected-class-times.txt as its expected times. The model: the thread
that forks the classes takes them from the end of the list, the other workers from the front; a
worker that takes a class whose lock another holds waits, idle; @Isolated classes run one after
the other once the rest are done. An estimate on one run's times, not a measurement: classes take
longer the more of them share the cores.
"""
import collections
import heapq
import os
import re
import sys


def read_times(path):
    times = {}
    for line in open(path, encoding="utf-8"):
        f = line.split()
        if len(f) >= 2 and not f[0].startswith("#"):
            try:
                times[f[1]] = max(times.get(f[1], 0.0), float(f[0]))
            except ValueError:
                pass
    return times


def read_locks(src):
    """Class name -> the names of its class-level locks; 'ISOLATED' for @Isolated."""
    locks = {}
    for folder, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".java"):
                continue
            text = open(os.path.join(folder, f), encoding="utf-8").read()
            package = re.search(r"^package ([\w.]+);", text, re.M)
            declaration = re.search(r"^(?:public |final |abstract )*class " + re.escape(f[:-5]) + r"\b", text, re.M)
            head = text[:declaration.start()] if declaration else ""
            names = set(re.findall(r'@ResourceLock\(\s*(?:value\s*=\s*)?([\w."]+)', head))
            names = {n.replace("Shared.", "").strip('"') for n in names}
            if "@Isolated" in head:
                names.add("ISOLATED")
            locks[(package.group(1) + "." if package else "") + f[:-5]] = names
    return locks


def longest_first(classes, expected, locks, chained=True):
    """org.ripv.testing.LongestFirst's order (chained=False: before a lock's classes counted together)."""
    known = [expected[c] for c in classes if c in expected]
    average = sum(known) / len(known) if known else 1.0
    seconds = lambda c: expected.get(c, average)
    own = lambda c: locks.get(c, set()) - {"ISOLATED"}
    isolated = [c for c in classes if "ISOLATED" in locks.get(c, set())]
    front = [c for c in classes if c not in isolated and (own(c) or seconds(c) >= 2 * average)]
    back = [c for c in classes if c not in isolated and c not in front]
    key = lambda c: (seconds(c), c)
    isolated.sort(key=key, reverse=True)
    front.sort(key=key, reverse=True)
    back.sort(key=key)
    if chained:                       # a locked class counts as long as it and its lock's shorter classes
        left = collections.Counter()
        for c in front:
            for lock in own(c):
                left[lock] += seconds(c)
        due = {}
        for c in front:
            due[c] = seconds(c)
            for lock in own(c):
                due[c] = max(due[c], left[lock])
                left[lock] -= seconds(c)
        front.sort(key=lambda c: (due[c], seconds(c), c), reverse=True)
    spaced, previous = [], set()
    while front:
        pick = next((i for i, c in enumerate(front) if not previous & own(c)), 0)
        spaced.append(front.pop(pick))
        previous = own(spaced[-1])
    return isolated + spaced + back


def replay(order, times, locks, parallelism):
    """Seconds from the first class's start to the last one's end."""
    isolated = [c for c in order if "ISOLATED" in locks.get(c, set())]
    forked = [c for c in order if c not in isolated]
    holder = {}                       # lock -> worker
    waiting = collections.defaultdict(collections.deque)
    events, now, ends = [], 0.0, {}
    running = {}                      # worker -> class
    front, back = 0, len(forked) - 1
    taken = set()

    def start(worker, c):
        taken.add(c)
        running[worker] = c
        acquire(worker)

    def acquire(worker):
        c = running[worker]
        for lock in sorted(locks.get(c, set()) - {"ISOLATED"}):
            if holder.get(lock) not in (None, worker):
                waiting[lock].append(worker)
                return
            holder[lock] = worker
        heapq.heappush(events, (now + times.get(c, 0.0), worker))

    def next_class(worker):
        nonlocal front, back
        if worker == 0:               # the forking thread: from the back
            while back >= 0 and forked[back] in taken:
                back -= 1
            if back >= 0:
                start(0, forked[back])
        else:
            while front < len(forked) and forked[front] in taken:
                front += 1
            if front < len(forked):
                start(worker, forked[front])

    for w in range(parallelism):
        next_class(w)
    while events:
        now, worker = heapq.heappop(events)
        c = running.pop(worker)
        ends[c] = now
        freed = [lock for lock, w in holder.items() if w == worker]
        for lock in freed:
            del holder[lock]
        for lock in freed:
            if waiting[lock]:
                acquire(waiting[lock].popleft())
        next_class(worker)
        for w in range(parallelism):
            if w not in running:
                next_class(w)
    return now + sum(times.get(c, 0.0) for c in isolated)


def main():
    module = sys.argv[1]
    parallelism = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    times = read_times(os.path.join(module, "target", "class-times.txt"))
    locks = read_locks(os.path.join(module, "src", "test", "java"))
    expected_file = os.path.join(module, "src", "test", "resources", "expected-class-times.txt")
    expected = read_times(expected_file) if os.path.exists(expected_file) else {}
    order = longest_first(sorted(times), expected, locks)
    unchained = longest_first(sorted(times), expected, locks, chained=False)
    total = sum(times.values())
    print(f"{module}: {len(times)} classes, {total:.0f} s of their own time")
    print(f"LongestFirst, {parallelism} at a time, each class as long as in this run: {replay(order, times, locks, parallelism):.0f} s"
          f" (all of it spread evenly: {total / parallelism:.0f} s; without a lock's classes counted together:"
          f" {replay(unchained, times, locks, parallelism):.0f} s)")


if __name__ == "__main__":
    main()
