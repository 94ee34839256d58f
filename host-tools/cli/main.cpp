// Placeholder until the command line lands (issue 2).
#include <cstdio>
int main() { std::fprintf(stderr, "spinhash: not built yet\n"); return 2; }
