/* Test-harness workaround for a QEMU 7.2 bug (Debian 12's qemu-user), linked
 * only into 32-bit PowerPC test programs that run under qemu-ppc.
 *
 * glibc's powerpc libm (sin, cos, sincos, exp, atan2, ...) saves and sets the
 * rounding mode with mffscrni / mffscrn / mffsl. These ISA 3.0 encodings are
 * designed to execute as plain mffs on older processors, and real hardware
 * does so; QEMU 7.2's decodetree translator raises SIGILL for them on every
 * pre-POWER9 CPU model instead (fixed upstream later by falling back to mffs).
 * This handler emulates the three instructions from the signal context so the
 * unmodified libm runs. It never runs on hardware and touches no core code. */
#if defined(__powerpc__) && !defined(__powerpc64__) && defined(__linux__)

#define _GNU_SOURCE
#include <signal.h>
#include <stdint.h>
#include <string.h>
#include <ucontext.h>

enum {
  kPrimaryOpcode = 63,
  kMffsFamilyXo = 583, /* mffs and its ISA 3.0 variants */
  kMffscrn = 22,       /* field A selecting the variant */
  kMffscrni = 23,
  kMffsl = 24,
  kNipIndex = 32, /* gregs index of the next instruction address */
};
static const uint32_t kControlMask = 0xFFu;   /* VE OE UE ZE XE NI RN */
static const uint32_t kStatusMask = 0x7F000u; /* FR FI FPRF, returned by mffsl */
static const uint32_t kRoundingMask = 0x3u;

static uint64_t bits_of(double d) {
  uint64_t u;
  memcpy(&u, &d, sizeof u);
  return u;
}
static double double_of(uint64_t u) {
  double d;
  memcpy(&d, &u, sizeof d);
  return d;
}

static void emulate_mffs_variant(int sig, siginfo_t* info, void* context) {
  (void)sig;
  (void)info;
  ucontext_t* uc = (ucontext_t*)context;
  mcontext_t* mc = uc->uc_mcontext.uc_regs;
  const uint32_t insn = *(const uint32_t*)mc->gregs[kNipIndex];
  const uint32_t a = (insn >> 16) & 0x1Fu, rt = (insn >> 21) & 0x1Fu, rb = (insn >> 11) & 0x1Fu;
  const int family = (insn >> 26) == kPrimaryOpcode && ((insn >> 1) & 0x3FFu) == kMffsFamilyXo;
  if (!family || (a != kMffscrn && a != kMffscrni && a != kMffsl)) {
    signal(SIGILL, SIG_DFL); /* a genuine illegal instruction: die as usual */
    return;
  }
  const uint64_t fpscr = bits_of(mc->fpregs.fpscr);
  const uint32_t keep = a == kMffsl ? (kControlMask | kStatusMask) : kControlMask;
  const uint32_t rn = a == kMffscrni ? ((insn >> 11) & kRoundingMask)
                                     : ((uint32_t)bits_of(mc->fpregs.fpregs[rb]) & kRoundingMask);
  mc->fpregs.fpregs[rt] = double_of((fpscr & 0xFFFFFFFF00000000ull) | ((uint32_t)fpscr & keep));
  if (a != kMffsl) mc->fpregs.fpscr = double_of((fpscr & ~(uint64_t)kRoundingMask) | rn);
  mc->gregs[kNipIndex] += 4;
}

__attribute__((constructor)) static void install_mffs_emulation(void) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_sigaction = emulate_mffs_variant;
  sa.sa_flags = SA_SIGINFO;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGILL, &sa, 0);
}

#endif
