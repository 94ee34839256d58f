# Sourced by the instruction benchmarks: tests/worst_case/worst_case_runner
# reads a query as bare little-endian float64 x y z, which is the body of a
# binary PLY that `spinhash scan` writes. ply_body PLY OUT writes that body.
ply_body() {
  python3 -c 'import sys; b = open(sys.argv[1], "rb").read(); e = b"end_header\n"
open(sys.argv[2], "wb").write(b[b.index(e) + len(e):])' "$1" "$2"
}
