/* Replays a fuzz harness over every file of a corpus folder (used when libFuzzer is not
 * available), so the harnesses are built and their seed inputs run in every test pass. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Replays every file of `folder`; returns how many, or -1 if it cannot be read. */
static int replay_folder(const char *folder)
{
    DIR *dir = opendir(folder);
    if (!dir) return -1;
    int count = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        if (entry->d_name[0] == '.') continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        char *data;
        size_t size;
        if (sk_read_file(path, 64u << 20, &data, &size, NULL) != SK_OK) continue;
        LLVMFuzzerTestOneInput((const uint8_t *)data, size);
        free(data);
        count++;
    }
    closedir(dir);
    printf("replayed %d inputs from %s\n", count, folder);
    return count;
}

/* usage: replay CORPUS_DIR [REGRESSIONS_DIR]: the corpus must hold inputs; the folder of
   past findings may be absent (a reader without findings). */
int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: %s CORPUS_DIR [REGRESSIONS_DIR]\n", argv[0]);
        return 2;
    }
    int count = replay_folder(argv[1]);
    if (count < 0) {
        fprintf(stderr, "%s: cannot open corpus folder\n", argv[1]);
        return 1;
    }
    if (argc == 3) replay_folder(argv[2]);
    return count > 0 ? 0 : 1;
}
