/* gpu_data.h - the file tests/gpu/mist_gpu.cu writes and tests/gpu/gpu_check.c
 * reads: a header, then the arrays in the order of mist_gpu.cu's main. */
#ifndef GPU_DATA_H
#define GPU_DATA_H
#include <stdint.h>

enum { GP_HG, GP_DRAINE, GP_CS, GP_RAYLEIGH, GP_FOG };
#define GP_MAGIC 0x6d697374 /* "mist" */
#define GP_NRAND 100000      /* random points, kinds in turn */
#define GP_NSPECIAL (5 * 13 * 7 * 11) /* bad and edge inputs */
#define GP_NC 40             /* batches */
#define GP_CH 1100           /* elements a batch */

typedef struct {
    int32_t kind, pad;
    double g, a, xi, xi2;    /* eval at u = 2 xi2 - 1; xi2 also the azimuth's */
    double g2, w;            /* GP_FOG: mist_fog_make(g, g2, a, w) */
    double wi[3];
} gp_in;
typedef struct {             /* samples, prepared samples, evals, prepared evals */
    double ds, dp, de, dpe, dpdf, dwo[3];
    float  fs, fp, fe, fpe, fpdf, fwo[3];
} gp_out;
typedef struct { int32_t kind, pad; double g, a; } gp_chunk;
typedef struct { int32_t magic, n, nrand, nc, ch, pad; char device[104]; } gp_header;
#endif
