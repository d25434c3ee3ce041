/* Memory bandwidth for lbdem's roofline: the STREAM triad a[i] = b[i] + s c[i] on three double
 * arrays of about 1 GiB together, best of NTIMES passes, 24 B counted per element (two reads and
 * one write; write-allocate traffic not counted, as in STREAM).
 * build: gcc -O3 -march=native -fopenmp stream_triad.c -o stream_triad
 * run:   OMP_NUM_THREADS=1 ./stream_triad; OMP_NUM_THREADS=2 ./stream_triad */
#include <stdio.h>
#include <stdlib.h>
#include <omp.h>

#ifndef NTIMES
#define NTIMES 10
#endif

int main(int argc, char **argv) {
    size_t total_bytes = (argc > 1) ? (size_t)atoll(argv[1]) : ((size_t)1 << 30);
    size_t n = total_bytes / (3 * sizeof(double));
    double *a = aligned_alloc(64, n * sizeof(double));
    double *b = aligned_alloc(64, n * sizeof(double));
    double *c = aligned_alloc(64, n * sizeof(double));
    if (!a || !b || !c) { fprintf(stderr, "alloc failed\n"); return 1; }
    /* first-touch initialisation with the same static schedule as the kernel */
    #pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) { a[i] = 0.0; b[i] = 1.0; c[i] = 2.0; }
    const double s = 3.0;
    double best = 1e30;
    for (int k = 0; k < NTIMES; ++k) {
        double t0 = omp_get_wtime();
        #pragma omp parallel for schedule(static)
        for (size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
        double t = omp_get_wtime() - t0;
        if (t < best) best = t;
    }
    /* checksum so the compiler cannot drop the kernel */
    double chk = 0.0;
    for (size_t i = 0; i < n; i += 4096) chk += a[i];
    double gbs = 3.0 * sizeof(double) * (double)n / best / 1e9;
    printf("threads=%d n=%zu total_MiB=%.0f best_s=%.5f triad_GBps=%.2f chk=%.1f\n",
           omp_get_max_threads(), n, 3.0 * n * sizeof(double) / 1048576.0, best, gbs, chk);
    free(a); free(b); free(c);
    return 0;
}
