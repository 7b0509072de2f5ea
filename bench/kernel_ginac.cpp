// GiNaC side of the kernel benchmark (see bench/README.md).
//
// Prints one line per benchmark, tab-separated, the same protocol as
// kernel_qdot and kernel_sympy.py:  name reps median_s min_s size value
// Every repetition makes its own symbols and expressions and destroys them
// before the clock stops, as kernel_qdot does with a fresh context.
#include <ginac/ginac.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace GiNaC;

namespace {

struct Opts {
    double budget = 1.0;  // seconds of timed runs per benchmark
    int min_reps = 5;
    int max_reps = 1000;
};

// The evaluation point, the same in all three programs.
const double PX = 0.125, PY = 0.25, PZ = 0.375, PW = 0.5;

struct Syms {
    symbol x{"x"}, y{"y"}, z{"z"}, w{"w"};
};

std::vector<ex> expand1(const Syms &s) {
    return {pow(1 + s.x + s.y + s.z, 20).expand()};
}

std::vector<ex> expand2(const Syms &s) {
    ex e = pow(s.x + s.y + s.z + s.w, 15).expand();
    return {(e * e.diff(s.x)).expand()};
}

std::vector<ex> diff10(const Syms &s) {
    ex f = pow(sin(s.x), 4) * cos(s.x) * exp(s.x);
    return {f.diff(s.x, 10)};
}

std::vector<ex> trig200(const Syms &s) {
    ex sum = 0;
    for (int k = 1; k <= 200; k++)
        sum = sum + k * sin(k * s.x) * cos(k * s.y);
    return {sum.diff(s.x), sum.diff(s.y)};
}

struct Bench {
    const char *name;
    std::vector<ex> (*fn)(const Syms &);
};

const Bench BENCHES[] = {
    {"expand1", expand1}, {"expand2", expand2}, {"diff10", diff10}, {"trig200", trig200}};

size_t nterms(const ex &e) { return is_a<add>(e) ? e.nops() : 1; }

double value_at(const Syms &s, const ex &e) {
    ex v = e.subs(lst{s.x == PX, s.y == PY, s.z == PZ, s.w == PW}).evalf();
    return ex_to<numeric>(v).to_double();
}

// Untimed: the result's size (top-level terms, summed over the outputs) and
// its value at the point, to show the three systems computed the same thing.
void check(const Bench &b, size_t *size, double *value) {
    Syms s;
    *size = 0;
    *value = 0.0;
    for (const ex &e : b.fn(s)) {
        *size += nterms(e);
        *value += value_at(s, e);
    }
}

// Processor time of this process, as in kernel_qdot.
double now() {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double one_run(const Bench &b) {
    double t0 = now();
    {
        Syms s;
        std::vector<ex> r = b.fn(s);
        if (r.empty()) std::abort();
    }
    return now() - t0;
}

void run(const Bench &b, const Opts &o) {
    size_t size;
    double value;
    check(b, &size, &value);  // also the warm-up
    std::vector<double> t;
    double total = 0.0;
    while ((int)t.size() < o.max_reps && ((int)t.size() < o.min_reps || total < o.budget)) {
        t.push_back(one_run(b));
        total += t.back();
    }
    std::sort(t.begin(), t.end());
    size_t n = t.size();
    double med = n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
    std::printf("%s\t%zu\t%.6e\t%.6e\t%zu\t%.15g\n", b.name, n, med, t[0], size, value);
    std::fflush(stdout);
}

bool wanted(const char *name, int argc, char **argv, int first) {
    if (first >= argc) return true;
    for (int i = first; i < argc; i++)
        if (std::strcmp(argv[i], name) == 0) return true;
    return false;
}

}  // namespace

// Usage: kernel_ginac [--budget S] [--min-reps N] [--max-reps N] [names...]
int main(int argc, char **argv) {
    Opts o;
    int i = 1;
    for (; i + 1 < argc && std::strncmp(argv[i], "--", 2) == 0; i += 2) {
        if (!std::strcmp(argv[i], "--budget")) o.budget = std::atof(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--min-reps")) o.min_reps = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--max-reps")) o.max_reps = std::atoi(argv[i + 1]);
        else {
            std::fprintf(stderr, "kernel_ginac: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    for (const Bench &b : BENCHES)
        if (wanted(b.name, argc, argv, i)) run(b, o);
    return 0;
}
