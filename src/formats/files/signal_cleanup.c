/* Removal of unfinished outputs when the process is stopped by SIGINT, SIGTERM or SIGHUP:
 * temporary files of sk_atomic_file and the staged files and folders of sk_output_set
 * register here while they exist, and the handler removes them before the signal takes
 * its default course (the process ends with the same signal).
 *
 * This is the library's one piece of process-wide mutable state: a signal reaches the
 * process, not an object. The table is lock-free (atomic pointers), so threads may
 * register and unregister concurrently and the handler reads it at any moment. The
 * handler is installed only for signals whose disposition is still the default, so a
 * program with its own handlers keeps them. */
#define _GNU_SOURCE /* syscall (getdents64) */
#include "base/io_internal.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

#define SLOTS 256

static _Atomic(const char *) g_paths[SLOTS];
static atomic_bool g_folder[SLOTS];
static atomic_flag g_installed = ATOMIC_FLAG_INIT;
static const int k_signals[] = {SIGINT, SIGTERM, SIGHUP};

#if defined(__linux__) && defined(SYS_getdents64)
/* Linux directory entries as getdents64 returns them (async-signal-safe listing). */
struct linux_dirent64 {
    unsigned long long d_ino;
    long long d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[];
};
#endif

#if defined(__linux__) && defined(SYS_getdents64)
static void empty_folder(int fd, int depth);

/* Removes entry `name` of folder `dirfd`: a file, or a folder with what it holds (at most
   `depth` levels further down). */
static void remove_entry(int dirfd, const char *name, int depth)
{
    if (unlinkat(dirfd, name, 0) == 0 || depth <= 0) return;
    int fd = openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
        empty_folder(fd, depth - 1);
        close(fd);
    }
    unlinkat(dirfd, name, AT_REMOVEDIR);
}

static void empty_folder(int fd, int depth)
{
    char buf[2048] __attribute__((aligned(8)));
    for (;;) {
        long n = syscall(SYS_getdents64, fd, buf, sizeof buf);
        if (n <= 0) break;
        for (long off = 0; off < n;) {
            struct linux_dirent64 *e = (struct linux_dirent64 *)(buf + off);
            const char *name = e->d_name;
            if (!(name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'))))
                remove_entry(fd, name, depth);
            off += e->d_reclen;
        }
    }
}
#endif

/* Removes a staged folder with its files and subfolders (the outputs of one run, a few
 * levels deep at most). Only async-signal-safe calls. */
static void remove_folder(const char *path)
{
#if defined(__linux__) && defined(SYS_getdents64)
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        empty_folder(fd, 4);
        close(fd);
    }
#endif
    /* elsewhere (the WebAssembly build) there is no async-signal-safe listing: an empty
       folder is removed, a full one stays */
    rmdir(path);
}

void sk__cleanup_now(void)
{
    for (int i = 0; i < SLOTS; i++) {
        const char *path = atomic_load(&g_paths[i]);
        if (!path) continue;
        if (atomic_load(&g_folder[i]))
            remove_folder(path);
        else
            unlink(path);
    }
}

static void on_signal(int sig)
{
    sk__cleanup_now();
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install(void)
{
    if (atomic_flag_test_and_set(&g_installed)) return;
    for (size_t i = 0; i < sizeof k_signals / sizeof k_signals[0]; i++) {
        struct sigaction old;
        if (sigaction(k_signals[i], NULL, &old) != 0) continue;
        if (!(old.sa_flags & SA_SIGINFO) && old.sa_handler == SIG_DFL) {
            struct sigaction sa;
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = on_signal;
            sigemptyset(&sa.sa_mask);
            for (size_t k = 0; k < sizeof k_signals / sizeof k_signals[0]; k++)
                sigaddset(&sa.sa_mask, k_signals[k]);
            sigaction(k_signals[i], &sa, NULL);
        }
    }
}

int sk__cleanup_register(const char *path, bool folder)
{
    install();
    for (int i = 0; i < SLOTS; i++) {
        const char *expected = NULL;
        if (atomic_load(&g_paths[i]) == NULL &&
            atomic_compare_exchange_strong(&g_paths[i], &expected, path)) {
            atomic_store(&g_folder[i], folder);
            return i;
        }
    }
    return -1; /* table full: the path is still removed on failure, not on a signal */
}

void sk__cleanup_unregister(int slot)
{
    if (slot >= 0 && slot < SLOTS) atomic_store(&g_paths[slot], NULL);
}
