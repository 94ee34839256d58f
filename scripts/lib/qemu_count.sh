# Sourced by the instruction benchmarks: counting a target's instructions
# under qemu-user with the marker plugin scripts/qemu/insn_count.c (Debian's
# qemu ships no plugins, so it is built here).
#
# qemu_count_setup CALLER TARGET OUT [PLUGIN_ARG ...] builds OUT/insn_count.so
# and sets the array `qemu` to the command that runs a TARGET (aarch64 | arm)
# binary under it; each PLUGIN_ARG (say stage=NAME) is passed to the plugin.
# An unknown target exits 2 with a message naming CALLER.
qemu_count_setup() {
  local caller="$1" target="$2" out="$3"; shift 3
  local triple
  case "$target" in
    aarch64) triple=aarch64-linux-gnu ;;
    arm) triple=arm-linux-gnueabihf ;;
    *) echo "$caller: the target must be aarch64 or arm, not '$target'" >&2; exit 2 ;;
  esac
  local qemu_root
  qemu_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  mkdir -p "$out"
  gcc -shared -fPIC -O2 -o "$out/insn_count.so" "$qemu_root/scripts/qemu/insn_count.c"
  local plugin="$out/insn_count.so" arg
  for arg in "$@"; do plugin+=",$arg"; done
  qemu=("qemu-$target" -plugin "$plugin" -d plugin -L "/usr/$triple")
}
