/* mist_gpu.cu - mist in CUDA device code, run on a GPU.
 *
 * The same inputs go through the device and the host (the identical
 * __host__ __device__ function below) and are written to a file that
 * tests/gpu/gpu_check.c checks on any machine:
 *   - every device sample (scalar and prepared, float and double, HG,
 *     Draine, Cornette-Shanks, Rayleigh) against the __float128 inverse CDF
 *     of tests/mist_ref.h, with test_accuracy.c's bar (device code has no
 *     long double: the double samplers finish in double-double, with the
 *     same bar);
 *   - every device density against the __float128 density, beside the
 *     host's error on the same inputs;
 *   - bad input (NaN, inf, |g| > 1, alpha < 0, xi outside [0, 1), zero and
 *     NaN directions) and the fog mixture against the host's answers;
 *   - the batch forms (n = 1100: past the Draine samplers' preparing
 *     threshold of 1024) against the reference.
 * It also prints a throughput table: mist against the formulas as printed
 * (tests/mist_printed.h) on the same device in the same run.
 *
 * Not a ctest test (CI has no GPU).  With nvcc and a GPU:
 *   nvcc -O3 -arch=sm_90 -Iinclude -Itests tests/gpu/mist_gpu.cu -o mist_gpu
 *   ./mist_gpu gpu.bin
 *   cc -O2 -Iinclude -Itests tests/gpu/gpu_check.c -o gpu_check -lm
 *   ./gpu_check gpu.bin
 * (-arch: the GPU's; nvcc contracts a*b+c into fma by default, as a CUDA
 * renderer's build would.) */
#include "mist.h"
#include "mist_printed.h"
#include "gpu_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#define CK(x) do { cudaError_t e_ = (x); if (e_ != cudaSuccess) {                 \
    fprintf(stderr, "%s:%d: %s\n", __FILE__, __LINE__, cudaGetErrorString(e_));  \
    exit(1); } } while (0)

/* ------------------------------------------------------------------------ */
/* One point, on the host or the device                                      */
/* ------------------------------------------------------------------------ */

__host__ __device__ static void run_point(const gp_in *in, gp_out *o)
{
    double g = in->g, a = in->a, xi = in->xi, x2 = in->xi2, ue = 2 * in->xi2 - 1;
    float gf = (float)g, af = (float)a, xf = (float)xi, x2f = (float)x2, uef = (float)ue;
    mist_vec3 wi, wo;
    mist_vec3f wif, wof;
    mist_fog fog = mist_fog_make(g, in->g2, a, in->w);
    mist_fogf fogf = mist_fog_makef(gf, (float)in->g2, af, (float)in->w);
    mist_phase p;
    mist_phasef pf;
    wi.x = in->wi[0]; wi.y = in->wi[1]; wi.z = in->wi[2];
    wif.x = (float)wi.x; wif.y = (float)wi.y; wif.z = (float)wi.z;
    switch (in->kind) {
    case GP_HG:
        o->ds = mist_hg_sample(g, xi);           o->fs = mist_hg_samplef(gf, xf);
        o->de = mist_hg_eval(g, ue);             o->fe = mist_hg_evalf(gf, uef);
        wo = mist_hg_sample_dir(g, wi, xi, x2, &o->dpdf);
        wof = mist_hg_sample_dirf(gf, wif, xf, x2f, &o->fpdf);
        p = mist_phase_hg(g);                    pf = mist_phase_hgf(gf);
        break;
    case GP_DRAINE:
        o->ds = mist_draine_sample(g, a, xi);    o->fs = mist_draine_samplef(gf, af, xf);
        o->de = mist_draine_eval(g, a, ue);      o->fe = mist_draine_evalf(gf, af, uef);
        wo = mist_draine_sample_dir(g, a, wi, xi, x2, &o->dpdf);
        wof = mist_draine_sample_dirf(gf, af, wif, xf, x2f, &o->fpdf);
        p = mist_phase_draine(g, a);             pf = mist_phase_drainef(gf, af);
        break;
    case GP_CS:
        o->ds = mist_cs_sample(g, xi);           o->fs = mist_cs_samplef(gf, xf);
        o->de = mist_cs_eval(g, ue);             o->fe = mist_cs_evalf(gf, uef);
        wo = mist_cs_sample_dir(g, wi, xi, x2, &o->dpdf);
        wof = mist_cs_sample_dirf(gf, wif, xf, x2f, &o->fpdf);
        p = mist_phase_cs(g);                    pf = mist_phase_csf(gf);
        break;
    case GP_RAYLEIGH:
        o->ds = mist_rayleigh_sample(xi);        o->fs = mist_rayleigh_samplef(xf);
        o->de = mist_rayleigh_eval(ue);          o->fe = mist_rayleigh_evalf(uef);
        wo = mist_rayleigh_sample_dir(wi, xi, x2, &o->dpdf);
        wof = mist_rayleigh_sample_dirf(wif, xf, x2f, &o->fpdf);
        p = mist_phase_rayleigh();               pf = mist_phase_rayleighf();
        break;
    default:
        o->ds = mist_fog_sample(fog, xi);        o->fs = mist_fog_samplef(fogf, xf);
        o->de = mist_fog_eval(fog, ue);          o->fe = mist_fog_evalf(fogf, uef);
        wo = mist_fog_sample_dir(fog, wi, xi, x2, &o->dpdf);
        wof = mist_fog_sample_dirf(fogf, wif, xf, x2f, &o->fpdf);
        p = mist_phase_fog(fog);                 pf = mist_phase_fogf(fogf);
        break;
    }
    o->dp = mist_phase_sample(&p, xi);           o->fp = mist_phase_samplef(&pf, xf);
    o->dpe = mist_phase_eval(&p, ue);            o->fpe = mist_phase_evalf(&pf, uef);
    o->dwo[0] = wo.x; o->dwo[1] = wo.y; o->dwo[2] = wo.z;
    o->fwo[0] = wof.x; o->fwo[1] = wof.y; o->fwo[2] = wof.z;
}

/* One batch of GP_CH elements with one (g, alpha): HG or Draine. */
__host__ __device__ static void run_chunk(const gp_chunk *c, const double *xi, double *bd,
                                          float *bf, double *bpd, float *bpf)
{
    int j;
    float gf = (float)c->g, af = (float)c->a;
    for (j = 0; j < GP_CH; ++j) bf[j] = bpf[j] = (float)xi[j];
    if (c->kind == GP_HG) {
        mist_phase p = mist_phase_hg(c->g);
        mist_phasef pf = mist_phase_hgf(gf);
        mist_hg_sample_n(c->g, xi, bd, GP_CH);
        mist_hg_sample_nf(gf, bf, bf, GP_CH);
        mist_phase_sample_n(&p, xi, bpd, GP_CH);
        mist_phase_sample_nf(&pf, bpf, bpf, GP_CH);
    } else {
        mist_phase p = mist_phase_draine(c->g, c->a);
        mist_phasef pf = mist_phase_drainef(gf, af);
        mist_draine_sample_n(c->g, c->a, xi, bd, GP_CH);
        mist_draine_sample_nf(gf, af, bf, bf, GP_CH);
        mist_phase_sample_n(&p, xi, bpd, GP_CH);
        mist_phase_sample_nf(&pf, bpf, bpf, GP_CH);
    }
}

__global__ void k_points(const gp_in *in, gp_out *out, int n)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) run_point(in + i, out + i);
}

__global__ void k_chunks(const gp_chunk *c, const double *xi, double *bd, float *bf,
                         double *bpd, float *bpf, int nc)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    size_t o = (size_t)i * GP_CH;
    if (i < nc) run_chunk(c + i, xi + o, bd + o, bf + o, bpd + o, bpf + o);
}

/* ------------------------------------------------------------------------ */
/* Inputs                                                                     */
/* ------------------------------------------------------------------------ */

static uint64_t rng_s = 20261126u;
static double urand(void)              /* splitmix64, 53 bits */
{
    uint64_t z = (rng_s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}
/* g over the whole domain: 0, log-uniform magnitude down to 1e-9, uniform,
 * and within 1e-7 .. 1e-1 of +-1 */
static double rand_g(void)
{
    double s = urand() < 0.5 ? -1 : 1, r = urand();
    if (r < 0.05) return 0;
    if (r < 0.45) return s * pow(10, -9 * urand());
    if (r < 0.8) return s * urand();
    return s * (1 - pow(10, -1 - 6 * urand()));
}
static double rand_xi(int k)           /* uniform, crowded towards 0, towards 1 */
{
    double x = urand();
    return k % 3 == 1 ? pow(x, 8) : k % 3 == 2 ? 1 - pow(x, 8) : x;
}
static void rand_dir(double *w)
{
    double z = 2 * urand() - 1, r = sqrt(1 - z * z), ph = 6.283185307179586 * urand();
    w[0] = r * cos(ph); w[1] = r * sin(ph); w[2] = z;
}

static void make_inputs(std::vector<gp_in> &in, std::vector<gp_chunk> &ch,
                        std::vector<double> &cxi)
{
    const double nan = NAN, inf = INFINITY;
    const double sg[] = { nan, inf, -inf, 1, -1, 1.5, -1.5, 1 + 0x1p-52, 0, -0.0, 1e-310,
                          1 - 1e-7, -1e-8 };
    const double sa[] = { nan, -1, -0.0, 0, inf, 1e30, 17 };
    const double sx[] = { nan, -1, -0.0, 0, 1e-310, 0.5, 1 - 0x1p-53, 1 - 0x1p-24, 1, 2, inf };
    const double sw[][3] = { { 0, 0, 0 }, { nan, 0, 1 }, { 0, 0, 1 }, { 3, 4, 0 },
                             { inf, 0, 0 }, { 1e-300, 0, 1e-300 } };
    const double sww[] = { 0.3, nan, -1, 2, 0, 1 };
    int i, k, ig, ia, ix, n = 0;
    in.resize(GP_NRAND + GP_NSPECIAL);
    for (i = 0; i < GP_NRAND; ++i) {
        gp_in *p = &in[i];
        p->kind = i % 5;
        p->g = rand_g();
        p->g2 = rand_g();
        p->a = urand() < 0.1 ? (urand() < 0.5 ? 0 : 1) : pow(10, -8 + 16 * urand());
        p->w = urand();
        p->xi = rand_xi(i / 5);
        p->xi2 = urand();
        rand_dir(p->wi);
    }
    for (k = 0; k < 5; ++k)
        for (ig = 0; ig < 13; ++ig)
            for (ia = 0; ia < 7; ++ia)
                for (ix = 0; ix < 11; ++ix) {
                    gp_in *p = &in[GP_NRAND + n];
                    p->kind = k;
                    p->g = sg[ig];
                    p->g2 = sg[(ig + ix) % 13];
                    p->a = sa[ia];
                    p->w = sww[(ia + ix) % 6];
                    p->xi = sx[ix];
                    p->xi2 = sx[(ix + ig + ia) % 11];
                    memcpy(p->wi, sw[(n / 3) % 6], sizeof p->wi);
                    ++n;
                }
    ch.resize(GP_NC);
    cxi.resize((size_t)GP_NC * GP_CH);
    for (i = 0; i < GP_NC; ++i) {
        ch[i].kind = i % 4 == 0 ? GP_HG : GP_DRAINE;
        ch[i].g = rand_g();
        ch[i].a = pow(10, -3 + 8 * urand());
        for (k = 0; k < GP_CH; ++k) cxi[(size_t)i * GP_CH + k] = rand_xi(k);
    }
}

/* ------------------------------------------------------------------------ */
/* Throughput: each thread draws its own xi stream (an LCG) and sums the     */
/* results; the same launch for mist and for the printed formula.            */
/* ------------------------------------------------------------------------ */

#define TIME_ITERS 2048
template <class F>
__global__ void k_time(F f, float *out)
{
    unsigned i = blockIdx.x * blockDim.x + threadIdx.x, s = i * 2654435761u + 12345u, it;
    float acc = 0;
    for (it = 0; it < TIME_ITERS; ++it) {
        float x, y;
        s = s * 1664525u + 1013904223u;
        x = (s >> 8) * 0x1p-24f;
        s = s * 1664525u + 1013904223u;
        y = (s >> 8) * 0x1p-24f;             /* the medium, for the varying rows */
        acc += f(x, y);
    }
    out[i] = acc;
}

#define FN(NAME, EXPR)                                                              \
    struct NAME { float g, a; const mist_phasef *pf; const mist_phase *pd;           \
        __device__ float operator()(float x, float y) const {                          \
            (void)pf; (void)pd; (void)y; return (float)(EXPR); } };
FN(t_eq3f, hg_sample_printed(g, x))
FN(t_hgf, mist_hg_samplef(g, x))
FN(t_phf, mist_phase_samplef(pf, x))
FN(t_eq6f, draine_eq6f(g, a, x))
FN(t_drf, mist_draine_samplef(g, a, x))
FN(t_hgevp, hg_eval_printed(g, 2 * x - 1))
FN(t_hgev, mist_hg_evalf(g, 2 * x - 1))
FN(t_drevp, draine_eval_printed(g, a, 2 * x - 1))
FN(t_drev, mist_draine_evalf(g, a, 2 * x - 1))
FN(t_phev, mist_phase_evalf(pf, 2 * x - 1))
FN(t_eq3d, hg_sample_printed_d(g, (double)x))
FN(t_hgd, mist_hg_sample(g, (double)x))
FN(t_eq6d, draine_eq6(g, a, (double)x))
FN(t_drd, mist_draine_sample(g, a, (double)x))
FN(t_phd, mist_phase_sample(pd, (double)x))
/* a medium that varies per call (heterogeneous fog): g in [.05, .95], alpha in [1, 500] */
FN(t_eq3fv, hg_sample_printed(0.05f + 0.9f * y, x))
FN(t_hgfv, mist_hg_samplef(0.05f + 0.9f * y, x))
FN(t_eq6fv, draine_eq6f(0.05f + 0.9f * y, 1 + 499 * y, x))
FN(t_drfv, mist_draine_samplef(0.05f + 0.9f * y, 1 + 499 * y, x))

/* the compact prepared form (mist_phasec_*, 60 bytes in float), by value in
 * the functor as a closure would hold it; and prepared anew for each call
 * from a varying medium, as a closure built per shading point */
struct t_pcf {
    mist_phasecf c;
    __device__ float operator()(float x, float y) const { (void)y; return mist_phasec_samplef(&c, x); }
};
struct t_pcd {
    mist_phasec c;
    __device__ float operator()(float x, float y) const
        { (void)y; return (float)mist_phasec_sample(&c, (double)x); }
};
struct t_pcfv {
    __device__ float operator()(float x, float y) const
    {
        mist_phasecf c = mist_phasec_drainef(0.05f + 0.9f * y, 1 + 499 * y);
        return mist_phasec_samplef(&c, x);
    }
};

static float *t_out;
static int t_blocks, t_threads = 256;

template <class F>
static double time_one(F f)            /* ns per call, all threads together */
{
    cudaEvent_t a, b;
    float ms, v[7];
    int r;
    CK(cudaEventCreate(&a)); CK(cudaEventCreate(&b));
    k_time<<<t_blocks, t_threads>>>(f, t_out);      /* warm-up */
    CK(cudaDeviceSynchronize());
    for (r = 0; r < 7; ++r) {
        CK(cudaEventRecord(a));
        k_time<<<t_blocks, t_threads>>>(f, t_out);
        CK(cudaEventRecord(b));
        CK(cudaEventSynchronize(b));
        CK(cudaEventElapsedTime(&ms, a, b));
        v[r] = ms;
    }
    std::sort(v, v + 7);
    CK(cudaEventDestroy(a)); CK(cudaEventDestroy(b));
    return v[3] * 1e6 / ((double)t_blocks * t_threads * TIME_ITERS);
}

template <class F> static F mk(float g, float a, const mist_phasef *pf, const mist_phase *pd)
{
    F f; f.g = g; f.a = a; f.pf = pf; f.pd = pd; return f;
}

static void row(const char *what, double t, double base)
{
    printf("| %-46s | %8.4f | %6.2fx |\n", what, t * 1e3, t / base);
}

static void throughput(void)
{
    mist_phasef hpf_hg = mist_phase_hgf(0.8f), hpf_dr = mist_phase_drainef(0.5f, 17.0f);
    mist_phasef hpf_fog = mist_phase_fogf(mist_fog_makef(0.9f, 0.5f, 250.0f, 0.3f));
    mist_phasef hpf_f10 = mist_phase_fogf(mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f));
    mist_phase hpd_dr = mist_phase_draine(0.5, 17.0);
    mist_phasef *pf_hg, *pf_dr, *pf_fog, *pf_f10;
    mist_phase *pd_dr;
    cudaDeviceProp prop;
    double b;
    CK(cudaGetDeviceProperties(&prop, 0));
    t_blocks = prop.multiProcessorCount * 16;
    CK(cudaMalloc(&t_out, sizeof(float) * t_blocks * t_threads));
    CK(cudaMalloc(&pf_hg, sizeof *pf_hg)); CK(cudaMalloc(&pf_dr, sizeof *pf_dr));
    CK(cudaMalloc(&pf_fog, sizeof *pf_fog)); CK(cudaMalloc(&pd_dr, sizeof *pd_dr));
    CK(cudaMalloc(&pf_f10, sizeof *pf_f10));
    CK(cudaMemcpy(pf_f10, &hpf_f10, sizeof hpf_f10, cudaMemcpyHostToDevice));
    CK(cudaMemcpy(pf_hg, &hpf_hg, sizeof hpf_hg, cudaMemcpyHostToDevice));
    CK(cudaMemcpy(pf_dr, &hpf_dr, sizeof hpf_dr, cudaMemcpyHostToDevice));
    CK(cudaMemcpy(pf_fog, &hpf_fog, sizeof hpf_fog, cudaMemcpyHostToDevice));
    CK(cudaMemcpy(pd_dr, &hpd_dr, sizeof hpd_dr, cudaMemcpyHostToDevice));
    printf("\nThroughput on %s (%d SMs): %d threads x %d calls a launch, median of 7 launches;\n"
           "ps per call = launch time / calls; ratio against the first row of its group\n\n",
           prop.name, prop.multiProcessorCount, t_blocks * t_threads, TIME_ITERS);
    printf("| %-46s | %8s | %7s |\n|---|---:|---:|\n", "function (float unless marked)", "ps/call", "ratio");
    b = time_one(mk<t_eq3f>(0.8f, 0, 0, 0));   row("HG sample, printed eq. 3, g .8", b, b);
    row("mist_hg_samplef", time_one(mk<t_hgf>(0.8f, 0, 0, 0)), b);
    row("mist_phase_samplef (HG, prepared)", time_one(mk<t_phf>(0, 0, pf_hg, 0)), b);
    b = time_one(mk<t_eq6f>(0.5f, 17, 0, 0));  row("Draine sample, printed eq. 6, g .5 alpha 17", b, b);
    row("mist_draine_samplef", time_one(mk<t_drf>(0.5f, 17, 0, 0)), b);
    row("mist_phase_samplef (Draine, prepared)", time_one(mk<t_phf>(0, 0, pf_dr, 0)), b);
    {
        t_pcf c; c.c = mist_phasec_drainef(0.5f, 17.0f);
        row("mist_phasec_samplef (Draine, compact)", time_one(c), b);
        row("mist_phase_samplef (fog 10 um, prepared)", time_one(mk<t_phf>(0, 0, pf_f10, 0)), b);
        c.c = mist_phasec_fogf(mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f));
        row("mist_phasec_samplef (fog 10 um, compact)", time_one(c), b);
    }
    b = time_one(mk<t_hgevp>(0.8f, 0, 0, 0));  row("HG eval, printed eq. 2", b, b);
    row("mist_hg_evalf", time_one(mk<t_hgev>(0.8f, 0, 0, 0)), b);
    b = time_one(mk<t_drevp>(0.5f, 17, 0, 0)); row("Draine eval, printed eq. 5", b, b);
    row("mist_draine_evalf", time_one(mk<t_drev>(0.5f, 17, 0, 0)), b);
    row("mist_phase_evalf (fog, prepared)", time_one(mk<t_phev>(0, 0, pf_fog, 0)), b);
    b = time_one(mk<t_eq3fv>(0, 0, 0, 0));     row("HG sample, printed eq. 3, g varying per call", b, b);
    row("mist_hg_samplef, g varying per call", time_one(mk<t_hgfv>(0, 0, 0, 0)), b);
    b = time_one(mk<t_eq6fv>(0, 0, 0, 0));     row("Draine sample, eq. 6, g and alpha varying", b, b);
    row("mist_draine_samplef, g and alpha varying", time_one(mk<t_drfv>(0, 0, 0, 0)), b);
    row("mist_phasec_drainef + _samplef, each call", time_one(t_pcfv()), b);
    b = time_one(mk<t_eq3d>(0.8f, 0, 0, 0));   row("HG sample, printed eq. 3, double", b, b);
    row("mist_hg_sample (double)", time_one(mk<t_hgd>(0.8f, 0, 0, 0)), b);
    b = time_one(mk<t_eq6d>(0.5f, 17, 0, 0));  row("Draine sample, printed eq. 6, double", b, b);
    row("mist_draine_sample (double)", time_one(mk<t_drd>(0.5f, 17, 0, 0)), b);
    row("mist_phase_sample (double, Draine, prepared)", time_one(mk<t_phd>(0, 0, 0, pd_dr)), b);
    {
        t_pcd c; c.c = mist_phasec_draine(0.5, 17.0);
        row("mist_phasec_sample (double, Draine, compact)", time_one(c), b);
    }
}

/* ------------------------------------------------------------------------ */

template <class T> static T *to_dev(const std::vector<T> &v)
{
    T *d;
    CK(cudaMalloc(&d, sizeof(T) * v.size()));
    CK(cudaMemcpy(d, v.data(), sizeof(T) * v.size(), cudaMemcpyHostToDevice));
    return d;
}
template <class T> static void from_dev(std::vector<T> &v, const T *d)
{
    CK(cudaMemcpy(v.data(), d, sizeof(T) * v.size(), cudaMemcpyDeviceToHost));
}
template <class T> static void put(FILE *f, const std::vector<T> &v)
{
    if (fwrite(v.data(), sizeof(T), v.size(), f) != v.size()) { perror("write"); exit(1); }
}

int main(int argc, char **argv)
{
    std::vector<gp_in> in;
    std::vector<gp_chunk> ch;
    std::vector<double> cxi;
    size_t n, m, i;
    gp_header h;
    FILE *f;
    /* notime: no throughput table; hostonly: no GPU, the host's answers in
     * the device's place (to try gpu_check.c) */
    int hostonly = argc > 2 && !strcmp(argv[2], "hostonly");
    if (argc < 2) { fprintf(stderr, "usage: %s out.bin [notime|hostonly]\n", argv[0]); return 2; }
    make_inputs(in, ch, cxi);
    n = in.size(); m = cxi.size();
    std::vector<gp_out> dev(n), host(n);
    std::vector<double> bd(m), bpd(m), hbd(m), hbpd(m);
    std::vector<float> bf(m), bpf(m), hbf(m), hbpf(m);
    if (!hostonly) {
        gp_in *d_in = to_dev(in);
        gp_out *d_out = to_dev(dev);
        gp_chunk *d_ch = to_dev(ch);
        double *d_xi = to_dev(cxi), *d_bd = to_dev(bd), *d_bpd = to_dev(bpd);
        float *d_bf = to_dev(bf), *d_bpf = to_dev(bpf);
        CK(cudaDeviceSetLimit(cudaLimitStackSize, 32768));   /* k_chunks: 18.5 KB a thread (ptxas -v) */
        k_points<<<(unsigned)(n + 127) / 128, 128>>>(d_in, d_out, (int)n);
        CK(cudaGetLastError());
        k_chunks<<<(GP_NC + 63) / 64, 64>>>(d_ch, d_xi, d_bd, d_bf, d_bpd, d_bpf, GP_NC);
        CK(cudaGetLastError());
        CK(cudaDeviceSynchronize());
        from_dev(dev, d_out);
        from_dev(bd, d_bd); from_dev(bf, d_bf); from_dev(bpd, d_bpd); from_dev(bpf, d_bpf);
    }
    for (i = 0; i < n; ++i) run_point(&in[i], &host[i]);
    for (i = 0; i < GP_NC; ++i)
        run_chunk(&ch[i], &cxi[i * GP_CH], &hbd[i * GP_CH], &hbf[i * GP_CH], &hbpd[i * GP_CH],
                  &hbpf[i * GP_CH]);
    if (hostonly) { dev = host; bd = hbd; bf = hbf; bpd = hbpd; bpf = hbpf; }
    f = fopen(argv[1], "wb");
    if (!f) { perror(argv[1]); return 1; }
    memset(&h, 0, sizeof h);
    h.magic = GP_MAGIC; h.n = (int)n; h.nrand = GP_NRAND; h.nc = GP_NC; h.ch = GP_CH;
    if (hostonly) snprintf(h.device, sizeof h.device, "none (host only)");
    else {
        cudaDeviceProp prop;
        CK(cudaGetDeviceProperties(&prop, 0));
        snprintf(h.device, sizeof h.device, "%s (sm_%d%d)", prop.name, prop.major, prop.minor);
    }
    fwrite(&h, sizeof h, 1, f);
    put(f, in); put(f, dev); put(f, host); put(f, ch); put(f, cxi);
    put(f, bd); put(f, bf); put(f, bpd); put(f, bpf);
    put(f, hbd); put(f, hbf); put(f, hbpd); put(f, hbpf);
    fclose(f);
    printf("%s: %zu points, %d batches of %d, device %s\n", argv[1], n, GP_NC, GP_CH, h.device);
    if (argc < 3) throughput();
    return 0;
}
