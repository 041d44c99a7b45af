/* Shared by the benchmark's C peers: timing and the one-line JSON result. */
#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec / 1e9;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Prints {"n":…,"secs":…,"p50_us":…,"p90_us":…,"p99_us":…,"max_us":…} from latencies in seconds. */
static void print_result(double *lat, long n, double secs) {
    if (n == 0) {
        printf("{\"n\":0,\"secs\":%.6f}\n", secs);
        return;
    }
    qsort(lat, n, sizeof(double), cmp_double);
    printf("{\"n\":%ld,\"secs\":%.6f,\"p50_us\":%.1f,\"p90_us\":%.1f,\"p99_us\":%.1f,\"max_us\":%.1f}\n", n, secs,
           lat[n / 2] * 1e6, lat[n * 9 / 10] * 1e6, lat[n * 99 / 100] * 1e6, lat[n - 1] * 1e6);
    fflush(stdout);
}
#endif
