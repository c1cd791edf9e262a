/* replay.c — runs a libFuzzer target on the files named on the command line, for
 * compilers without libFuzzer (and for regression tests of saved inputs). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        if (!f) {
            perror(argv[i]);
            return 2;
        }
        uint8_t buf[1 << 16];
        size_t size = fread(buf, 1, sizeof buf, f);
        fclose(f);
        LLVMFuzzerTestOneInput(buf, size);
    }
    printf("%d input(s) replayed\n", argc - 1);
    return 0;
}
