/* Instructions executed between two marker functions, for the instruction
 * benchmark on emulated targets (scripts/instructions-per-query.sh --target).
 * Debian's qemu-user ships no TCG plugins (no libinsn.so) and no
 * qemu-plugin.h, so this declares the few entry points of QEMU's plugin API
 * it uses (stable since QEMU 4.2; plugin API version 1, as in QEMU 7.2).
 *
 *   gcc -shared -fPIC -O2 -o insn_count.so scripts/qemu/insn_count.c
 *   qemu-aarch64 -plugin ./insn_count.so,begin=spinhash_bench_begin,end=spinhash_bench_end \
 *       -d plugin -L /usr/aarch64-linux-gnu PROGRAM ...
 *
 * Counting starts when a translation block that begins in `begin` runs and
 * stops at one that begins in `end`; each block counts all its instructions
 * (blocks rarely exit early), as libinsn.so does. Prints "insns N" at exit. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS = 0 };
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb* tb);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void* userdata);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void* userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb* tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void* userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb* tb);
struct qemu_plugin_insn* qemu_plugin_tb_get_insn(const struct qemu_plugin_tb* tb, size_t idx);
const char* qemu_plugin_insn_symbol(const struct qemu_plugin_insn* insn);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void* userdata);
void qemu_plugin_outs(const char* string);

#define EXPORT __attribute__((visibility("default")))
EXPORT int qemu_plugin_version = 1;

enum { kPlain = 0, kBegin = 1, kEnd = 2, kKindBits = 2 };
static char begin_symbol[128] = "spinhash_bench_begin";
static char end_symbol[128] = "spinhash_bench_end";
static int counting; /* user mode, one vCPU: no locking */
static uint64_t instructions;

/* userdata: the block's instruction count and kind, packed in the pointer. */
static void on_block(unsigned int vcpu, void* userdata) {
  const uintptr_t packed = (uintptr_t)userdata;
  (void)vcpu;
  if ((packed & 3u) == kBegin) counting = 1;
  if ((packed & 3u) == kEnd) counting = 0;
  if (counting) instructions += packed >> kKindBits;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb* tb) {
  const size_t n = qemu_plugin_tb_n_insns(tb);
  const char* symbol = n > 0 ? qemu_plugin_insn_symbol(qemu_plugin_tb_get_insn(tb, 0)) : NULL;
  uintptr_t kind = kPlain;
  (void)id;
  if (symbol != NULL && strcmp(symbol, begin_symbol) == 0) kind = kBegin;
  if (symbol != NULL && strcmp(symbol, end_symbol) == 0) kind = kEnd;
  qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS,
                                       (void*)(((uintptr_t)n << kKindBits) | kind));
}

static void on_exit(qemu_plugin_id_t id, void* userdata) {
  char line[64];
  (void)id;
  (void)userdata;
  snprintf(line, sizeof line, "insns %llu\n", (unsigned long long)instructions);
  qemu_plugin_outs(line);
}

static void copy_arg(char* out, size_t size, const char* value) { snprintf(out, size, "%s", value); }

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc, char** argv) {
  (void)info;
  for (int i = 0; i < argc; ++i) {
    if (strncmp(argv[i], "begin=", 6) == 0) copy_arg(begin_symbol, sizeof begin_symbol, argv[i] + 6);
    if (strncmp(argv[i], "end=", 4) == 0) copy_arg(end_symbol, sizeof end_symbol, argv[i] + 4);
  }
  qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
  qemu_plugin_register_atexit_cb(id, on_exit, NULL);
  return 0;
}
