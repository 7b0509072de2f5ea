/*
 * GiNaC side of the n-link pendulum benchmark (see bench/README.md).
 *
 * GiNaC has no Lagrange module, so this is the derivation a GiNaC user would
 * write by hand: coordinates q_i and velocities v_i as plain symbols, the
 * total time derivative of a function of q by the chain rule
 * (d/dt x = sum_k dx/dq_k v_k), and then
 *
 *     M_jk = d^2 L / dv_j dv_k,
 *     f_j  = dL/dq_j - sum_k d(dL/dv_j)/dq_k v_k,
 *
 * which is M q'' = f as SymPy's LagrangesMethod gives it (no time-dependent
 * terms here).  Nothing is simplified (GiNaC has no trigonometric
 * simplification), so this compares with SymPy's unsimplified equations.
 *
 * Prints one tab-separated line per n:  n reps median_s min_s nodes
 * (nodes: GiNaC's own tree size, not comparable between systems; the
 * driver measures count_ops from `--print N`, which prints M and f, one
 * entry a line, with theta<i> for q_i and thetad<i> for v_i).
 */
#include <ginac/ginac.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

using namespace GiNaC;

struct eom {
    std::vector<ex> M, f;
};

static ex dt(const ex &e, const std::vector<symbol> &q, const std::vector<symbol> &v) {
    ex r = 0;
    for (size_t k = 0; k < q.size(); k++)
        r += e.diff(q[k]) * v[k];
    return r;
}

static eom derive(int n) {
    std::vector<symbol> q, v, m, l;
    for (int i = 1; i <= n; i++) {
        q.emplace_back("theta" + std::to_string(i));
        v.emplace_back("thetad" + std::to_string(i));
        m.emplace_back("m" + std::to_string(i));
        l.emplace_back("l" + std::to_string(i));
    }
    symbol g("g");
    ex x = 0, y = 0, T = 0, V = 0;
    for (int i = 0; i < n; i++) {
        x += l[i] * sin(q[i]);
        y -= l[i] * cos(q[i]);
        ex xd = dt(x, q, v), yd = dt(y, q, v);
        T += m[i] / 2 * (pow(xd, 2) + pow(yd, 2));
        V += m[i] * g * y;
    }
    ex L = T - V;
    eom e;
    for (int j = 0; j < n; j++) {
        ex p = L.diff(v[j]);
        for (int k = 0; k < n; k++)
            e.M.push_back(p.diff(v[k]));
        e.f.push_back(L.diff(q[j]) - dt(p, q, v));
    }
    return e;
}

static double now() {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

static size_t nodes(const ex &e) {
    size_t s = 1;
    for (size_t i = 0; i < e.nops(); i++)
        s += nodes(e.op(i));
    return s;
}

static void run(int n, double budget, int min_reps, int max_reps) {
    eom e = derive(n); // the warm-up, and the size
    size_t size = 0;
    for (const ex &x : e.M)
        size += nodes(x);
    for (const ex &x : e.f)
        size += nodes(x);
    std::vector<double> t;
    double total = 0;
    while (int(t.size()) < max_reps && (int(t.size()) < min_reps || total < budget)) {
        double t0 = now();
        { eom r = derive(n); } // destroyed inside the timed region
        t.push_back(now() - t0);
        total += t.back();
    }
    std::sort(t.begin(), t.end());
    size_t k = t.size();
    double med = k % 2 ? t[k / 2] : 0.5 * (t[k / 2 - 1] + t[k / 2]);
    std::printf("%d\t%zu\t%.6e\t%.6e\t%zu\n", n, k, med, t[0], size);
    std::fflush(stdout);
}

static void print(int n) {
    eom e = derive(n);
    for (const ex &x : e.M)
        std::cout << x << "\n";
    for (const ex &x : e.f)
        std::cout << x << "\n";
}

/* Usage: pendulum_ginac [--budget S] [--min-reps N] [--max-reps N] [n...]
 *        pendulum_ginac --print N */
int main(int argc, char **argv) {
    double budget = 1.0;
    int min_reps = 5, max_reps = 1000, i = 1;
    for (; i + 1 < argc && std::strncmp(argv[i], "--", 2) == 0; i += 2) {
        if (!std::strcmp(argv[i], "--budget"))
            budget = std::atof(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--min-reps"))
            min_reps = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--max-reps"))
            max_reps = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--print")) {
            print(std::atoi(argv[i + 1]));
            return 0;
        } else {
            std::fprintf(stderr, "pendulum_ginac: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if (max_reps < 1 || min_reps > max_reps)
        return 2;
    if (i >= argc)
        for (int n : {2, 4, 8, 16, 32})
            run(n, budget, min_reps, max_reps);
    for (; i < argc; i++)
        run(std::atoi(argv[i]), budget, min_reps, max_reps);
    return 0;
}
