#!/usr/bin/env bash
# The products (src/products/*: pictures, map sets, the showcase) start no program (the
# showcase's MP4 comes from the caller's encoder; the command's runs ffmpeg) and call the
# thread runtime only through the base. Usage: products_start_no_program.sh ROOT BUILD
set -euo pipefail
here=$(dirname "$0")
# OpenMP runtime calls a source may make (omp_get_thread_num and omp_get_num_threads are
# left out: gcc emits them for every statically scheduled "omp for" pragma)
runtime='omp_set_[a-z_]*|omp_get_max_threads|omp_get_num_procs|omp_in_parallel|omp_pause_[a-z_]*|omp_get_wtime|omp_[a-z_]*_lock'
exec bash "$here/module_imports.sh" "$1" "$2" products \
    "start no program and call the thread runtime only through the base" \
    'posix_spawn|posix_spawnp|fork|vfork|execv|execvp|execve|execl|execlp|system|popen|$runtime'
