#!/usr/bin/env python3
"""Worst-case stack of the core's entry points, from GCC's call graphs.

Reads every *.ci file (GCC -fcallgraph-info=su) under a build tree: nodes
carry each function's frame from -fstack-usage, edges its direct calls.
Prints, for each root, the deepest call chain and its total, and fails when
  - a total exceeds --budget,
  - a function on a reachable path has an unbounded dynamic frame,
  - the graph below a root has a cycle (recursion: the core has none).
Functions whose frame is unknown (libm, compiler helpers, the C library) add
--external-allowance bytes each where a chain ends in them; indirect calls
(only the log hook's, into firmware code) add --indirect-allowance.

  scripts/stack_report.py BUILD_DIR --budget 4096 [--root PATTERN ...]
"""
import argparse
import os
import re
import sys

NODE_RE = re.compile(r'^node: \{ title: "([^"]*)" label: "([^"]*)"')
EDGE_RE = re.compile(r'^edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"')
FRAME_RE = re.compile(r'(\d+) bytes \(([a-z,]+)\)')
INDIRECT = "__indirect_call"
# Demangled-name prefixes of the entry points firmware calls.
DEFAULT_ROOTS = [
    "spinhash::Database::open(",
    "spinhash::Recognizer::init(",
    "spinhash::Recognizer::recognize(",
    "spinhash_database_open(",
    "spinhash_recognizer_init(",
    "spinhash_recognize_f32(",
    "spinhash_recognize_f64(",
]


class Function:
    def __init__(self, title):
        self.title = title
        self.name = title
        self.frame = None  # bytes; None: not compiled with -fcallgraph-info (external)
        self.kind = ""
        self.calls = set()


def function_name(label):
    """The demangled signature without the return type, e.g. 'ns::f(int)'."""
    first = label.split("\\n")[0]
    paren = first.find("(")
    head = first[:paren] if paren >= 0 else first
    return head.split(" ")[-1] + (first[paren:] if paren >= 0 else "")


def load(build_dir):
    graph = {}
    for dirpath, _, files in os.walk(build_dir):
        for f in files:
            if not f.endswith(".ci"):
                continue
            with open(os.path.join(dirpath, f), encoding="utf-8", errors="replace") as fh:
                for line in fh:
                    m = NODE_RE.match(line)
                    if m:
                        fn = graph.setdefault(m.group(1), Function(m.group(1)))
                        frame = FRAME_RE.search(m.group(2))
                        if frame:  # the defining translation unit
                            fn.frame, fn.kind = int(frame.group(1)), frame.group(2)
                            fn.name = function_name(m.group(2))
                        elif fn.frame is None:
                            fn.name = function_name(m.group(2))
                        continue
                    m = EDGE_RE.match(line)
                    if m:
                        graph.setdefault(m.group(1), Function(m.group(1))).calls.add(m.group(2))
                        graph.setdefault(m.group(2), Function(m.group(2)))
    return graph


def worst_chains(graph, args):
    """Deepest chain below every function (memoised DFS); raises on a cycle."""
    memo, on_stack = {}, set()

    def cost(title, path):
        if title in memo:
            return memo[title]
        if title in on_stack:
            cycle = path[path.index(title):] + [title]
            raise RecursionError(" -> ".join(graph[t].name for t in cycle))
        fn = graph[title]
        if title == INDIRECT:
            memo[title] = (args.indirect_allowance, [title])
            return memo[title]
        if fn.frame is None:
            memo[title] = (args.external_allowance, [title])
            return memo[title]
        on_stack.add(title)
        best = (0, [])
        for callee in sorted(fn.calls):
            c = cost(callee, path + [title])
            if c[0] > best[0]:
                best = c
        on_stack.discard(title)
        memo[title] = (fn.frame + best[0], [title] + best[1])
        return memo[title]

    return cost


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build_dir")
    ap.add_argument("--budget", type=int, required=True, help="bytes allowed for any root's worst chain")
    ap.add_argument("--root", action="append", help="demangled-name prefix of an entry point (repeatable)")
    ap.add_argument("--external-allowance", type=int, default=256,
                    help="bytes assumed for a function without a frame record (libm, libgcc)")
    ap.add_argument("--indirect-allowance", type=int, default=256,
                    help="bytes assumed for an indirect call (the firmware's log hook)")
    args = ap.parse_args()

    graph = load(args.build_dir)
    if not any(fn.frame is not None for fn in graph.values()):
        sys.exit(f"stack_report: no *.ci files with frames under {args.build_dir} (build with -fcallgraph-info=su)")
    roots = args.root or DEFAULT_ROOTS
    cost = worst_chains(graph, args)
    failed = recursion = False
    unbounded = sorted({fn.name for fn in graph.values() if fn.kind and "dynamic" in fn.kind
                        and "bounded" not in fn.kind})
    print(f"stack report for {args.build_dir} (budget {args.budget} bytes)")
    for prefix in roots:
        matches = [t for t, fn in graph.items() if fn.frame is not None and fn.name.startswith(prefix)]
        if not matches:
            print(f"  {prefix}...: not found")
            failed = True
            continue
        for title in sorted(matches):
            try:
                total, chain = cost(title, [])
            except RecursionError as cycle:
                print(f"  RECURSION below {graph[title].name}: {cycle}")
                failed = recursion = True
                continue
            verdict = "ok" if total <= args.budget else "OVER BUDGET"
            failed |= total > args.budget
            print(f"  {graph[title].name}: {total} bytes [{verdict}]")
            for t in chain:
                fn = graph[t]
                frame = f"{fn.frame:6d}" if fn.frame is not None else "  (ext)" if t != INDIRECT else "  (ind)"
                print(f"      {frame}  {fn.name if t != INDIRECT else 'indirect call (log hook)'}")
    if not recursion:
        print("  no recursion below the roots (the call graph is acyclic)")
    if unbounded:
        print("  UNBOUNDED dynamic frames: " + ", ".join(unbounded))
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
