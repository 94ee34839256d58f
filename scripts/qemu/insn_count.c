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
 * (blocks rarely exit early), as libinsn.so does. Prints "insns N" at exit.
 *
 * Stages (scripts/instructions-per-point.sh): each argument stage=NAME also
 * counts between spinhash_bench_NAME_begin and spinhash_bench_NAME_end (up
 * to 15 stages; they may nest in the whole run) and prints "insns.NAME N". */
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

enum { kPlain = 0, kBegin = 1, kEnd = 2, kKindBits = 2, kCounterBits = 4, kMaxCounters = 1 << kCounterBits };
enum { kShift = kKindBits + kCounterBits };

/* A pair of markers and the instructions run between their calls. */
struct counter {
  char name[32];
  char begin[128];
  char end[128];
  int counting; /* user mode, one vCPU: no locking */
  uint64_t instructions;
};
/* Counter 0 is the whole run ("insns N"); stage=NAME adds one per stage. */
static struct counter counters[kMaxCounters] = {{"", "spinhash_bench_begin", "spinhash_bench_end", 0, 0}};
static unsigned counter_count = 1;

/* userdata: the block's instruction count, its marker's counter and kind,
 * packed in the pointer. */
static void on_block(unsigned int vcpu, void* userdata) {
  const uintptr_t packed = (uintptr_t)userdata;
  const unsigned kind = (unsigned)(packed & ((1u << kKindBits) - 1u));
  struct counter* marked = &counters[(packed >> kKindBits) & (kMaxCounters - 1u)];
  (void)vcpu;
  if (kind == kBegin) marked->counting = 1;
  if (kind == kEnd) marked->counting = 0;
  for (unsigned i = 0; i < counter_count; ++i)
    if (counters[i].counting) counters[i].instructions += packed >> kShift;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb* tb) {
  const size_t n = qemu_plugin_tb_n_insns(tb);
  const char* symbol = n > 0 ? qemu_plugin_insn_symbol(qemu_plugin_tb_get_insn(tb, 0)) : NULL;
  uintptr_t kind = kPlain, which = 0;
  (void)id;
  for (unsigned i = 0; symbol != NULL && i < counter_count; ++i) {
    if (strcmp(symbol, counters[i].begin) == 0) kind = kBegin, which = i;
    if (strcmp(symbol, counters[i].end) == 0) kind = kEnd, which = i;
  }
  qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS,
                                       (void*)(((uintptr_t)n << kShift) | (which << kKindBits) | kind));
}

static void on_exit(qemu_plugin_id_t id, void* userdata) {
  char line[96];
  (void)id;
  (void)userdata;
  snprintf(line, sizeof line, "insns %llu\n", (unsigned long long)counters[0].instructions);
  qemu_plugin_outs(line);
  for (unsigned i = 1; i < counter_count; ++i) {
    snprintf(line, sizeof line, "insns.%s %llu\n", counters[i].name,
             (unsigned long long)counters[i].instructions);
    qemu_plugin_outs(line);
  }
}

static void copy_arg(char* out, size_t size, const char* value) { snprintf(out, size, "%s", value); }

/* stage=NAME: counts between spinhash_bench_NAME_begin and _end as well. */
static void add_stage(const char* name) {
  if (counter_count == kMaxCounters) return;
  struct counter* c = &counters[counter_count];
  copy_arg(c->name, sizeof c->name, name);
  snprintf(c->begin, sizeof c->begin, "spinhash_bench_%s_begin", name);
  snprintf(c->end, sizeof c->end, "spinhash_bench_%s_end", name);
  ++counter_count;
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc, char** argv) {
  (void)info;
  for (int i = 0; i < argc; ++i) {
    if (strncmp(argv[i], "begin=", 6) == 0)
      copy_arg(counters[0].begin, sizeof counters[0].begin, argv[i] + 6);
    if (strncmp(argv[i], "end=", 4) == 0) copy_arg(counters[0].end, sizeof counters[0].end, argv[i] + 4);
    if (strncmp(argv[i], "stage=", 6) == 0) add_stage(argv[i] + 6);
  }
  qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
  qemu_plugin_register_atexit_cb(id, on_exit, NULL);
  return 0;
}
