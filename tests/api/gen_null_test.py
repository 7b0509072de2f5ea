#!/usr/bin/env python3
"""tests/api/gen_null_test.py - write tests/api/test_null.c from include/qdot/*.h.

Every QD_API function is called once with NULL in each of its pointer
arguments, the others valid where a fixture of their type exists (a context,
a model, its equations of motion, an expression, buffers), else NULL too.
What a call must return follows from its return type (the convention the
headers state): qd_status QD_ERR_ARG, a pointer NULL, a size_t 0, a bool
false, a double NaN; other types and void only must not crash (ASan).

    gen_null_test.py --root DIR            rewrite tests/api/test_null.c
    gen_null_test.py --root DIR --check    fail when it is out of date, so a
                                           new public function without its
                                           NULL calls fails ctest

Exceptions are the two tables below, each entry a documented behaviour.
"""
import argparse
import glob
import os
import re
import sys

# Arguments documented as accepting NULL with a meaning (defaults, "not
# wanted"): the call with that one NULL is not made, since it may succeed.
NULLABLE = {
    'qd_impulse_state_read': {'at'},
    'qd_flow_setup_run': {'write', 'data'},
    'qd_action_at': {'opts'},
    'qd_action_of_sep': {'opts'},
    'qd_canonical_check': {'t'},
    'qd_json_string': {'s'},
    'qd_json_commit': {'j'},
    'qd_modes_at_point': {'given'},
    'qd_json_expr': {'x'},
    'qd_codegen_c': {'h_text'},
    'qd_codegen_speeds_c': {'h_text'},
    'qd_codegen_model_c': {'h_text', 'prefix'},  # issue 32: as qd_codegen_c's
    'qd_modes_rest_note': {'out'},  # issue 32: NULL asks only whether there is a note
    'qd_equilibria_find_text': {'guess', 'box', 'where'},  # issue 32: options not given
    'qd_modes_scan_text': {'about', 'where'},  # issue 32: the chosen equilibrium; not wanted
    'qd_zvc_level_read': {'level', 'through', 'at', 'where'},  # issue 32: one of three
    'qd_action_state_read': {'at'},  # issue 32: the model's initial state alone
    'qd_speeds_modes_scan_text': {'about', 'where'},  # issue 32: the first equilibrium
    'qd_ctx_error_about': {'hint', 'name'},
    'qd_ctx_new_with': {'a'},
    'qd_ctx_set_progress': {'fn', 'data'},  # issue 34: NULL turns the progress off
    'qd_diag_format': {'file', 'text'},
    'qd_eom_derive_opts': {'opts'},
    'qd_eom_eval': {'M', 'R', 'f', 'lambda', 'qdd'},
    'qd_eom_prog_eval': {'M', 'R', 'f', 'lambda', 'qdd'},
    'qd_eom_reaction': {'residual'},
    'qd_render_eom': {'o'},
    'qd_render_speeds': {'o'},
    'qd_render_check': {'o'},
    'qd_render_hamiltonian': {'source', 'at'},  # w31-C: the model's name, symbolic
    'qd_phase_bracket_print': {'G'},  # w31-H: G NULL is dF/dt
    'qd_read_variable': {'err'},  # w31-H: the copy of the record not wanted
    'qd_equilibria_find': {'opts'},
    'qd_constrained_equilibria_find': {'opts'},
    'qd_constrained_linear_about': {'indep'},
    'qd_constrained_at_solve': {'indep'},
    'qd_modes_at_choose': {'about'},
    'qd_linearize_about': {'about'},
    'qd_tangent_new': {'vary'},
    'qd_tangent_jacobian': {'out'},
    'qd_conlin_about': {'independent'},
    'qd_conlin_point': {'about'},
    'qd_conlin_scan_run': {'about', 'independent'},
    'qd_conlin_render': {'lqr'},
    'qd_eom_request_render': {'failed'},
    'qd_linpoint_read': {'qd'},
    'qd_linpoint_set': {'qd'},
    'qd_eval': {'syms', 'vals'},
    'qd_periods_reduce': {'f'},  # no function: the fundamental system alone
    'qd_render_periods': {'f'},
    'qd_gram_schmidt': {'T'},  # the identity (App. 21 Thm 1)
    'qd_render_gram': {'x', 'T'},  # no names; the identity
    'qd_change_vars': {'f'},  # the Jacobian alone
    'qd_condensed_new': {'H'},  # no Hamilton's equations
    'qd_field_modes_compute': {'opts'},
    'qd_field_parse': {'diag', 'opts'},
    'qd_free_symbols': {'out'},
    'qd_generate': {'H'},
    'qd_generate_f2': {'H'},
    'qd_ham_derive': {'e'},
    'qd_hj_derive': {'opts'},
    'qd_impulse_solve': {'opts'},
    'qd_integrals_derive': {'opts'},
    # issue 31's renderers (w31-cmds-a): the model's name, a given force, the find's options
    'qd_routh_print': {'model_name'},
    'qd_routh_json': {'model_name'},
    'qd_routh_ignore_read': {'e', 'where'},
    'qd_hj_print': {'model_name'},
    'qd_hj_json': {'model_name'},
    'qd_integrals_print': {'g', 'model_name'},
    'qd_integrals_json': {'g', 'model_name'},
    'qd_metric_print': {'G'},
    'qd_metric_json': {'G'},
    'qd_path_print': {'opts'},
    'qd_poincare_json_begin': {'model', 'names'},
    'qd_json_add_model': {'model'},
    'qd_legendre_inverse_p': {'pdef'},
    'qd_linearize': {'syms', 'vals'},
    'qd_lqr_feedback': {'syms', 'vals'},
    'qd_lqr_print': {'s'},
    'qd_lqr_json': {'s'},
    'qd_flow_run': {'fo'},
    'qd_lyap_run': {'err'},
    'qd_scene_points': {'ctx'},
    'qd_state_layout': {'q'},
    'qd_state_append': {'vals'},
    'qd_state_read': {'opts'},
    'qd_state_value': {'m'},
    'qd_scene_analyse': {'ctx', 'skip'},
    'qd_lyap_run_stats': {'err', 'stats'},
    'qd_model_add_statement': {'diag'},
    'qd_model_add_given': {'label', 'diag'},
    'qd_model_parse': {'diag'},
    'qd_model_parse_opts': {'diag', 'opts'},
    'qd_model_where': {'where'},
    'qd_metric_force': {'up', 'phys', 'ord'},
    'qd_modes_scan': {'opts'},
    'qd_native_load': {'cache_dir'},
    'qd_native_load_run': {'cache_dir'},
    'qd_orbit_derive': {'ign'},
    'qd_orbit_solve': {'energy'},
    'qd_path_foci': {'legendre'},
    'qd_path_foci_free': {'ctx', 'foci'},
    'qd_path_foci_mult': {'legendre', 'mult'},
    'qd_path_foci_mult_free': {'ctx'},
    'qd_plot_add': {'index', 'label'},
    'qd_plot_add_map': {'label'},
    'qd_poincare_csv': {'row'},  # the header
    'qd_symmetry_modes_plot': {'s'},  # res's own modes
    'qd_plot_math_text': {'out'},
    'qd_plot_set_heading': {'text'},
    'qd_plot_set_note': {'text'},
    'qd_print': {'e'},
    'qd_prog_free': {'p'},
    'qd_prog_new': {'ctx', 'inputs', 'outputs'},
    'qd_prog_ninstr': {'p'},
    'qd_prog_run': {'in', 'out', 'p'},
    'qd_read': {'err', 'opts'},
    'qd_routh_derive_opts': {'opts'},
    'qd_scatter_from_model': {'ignore', 'mass'},
    'qd_sim_add_event': {'guard'},
    'qd_sim_columns': {'names'},
    'qd_sim_input_callback': {'data'},
    'qd_sim_load_native_taylor': {'cache_dir', 'cached'},
    'qd_sim_run': {'data', 'final', 'sink', 'stats'},
    'qd_sim_setup_state': {'syms', 'vals'},
    'qd_sim_setup_native': {'note'},
    'qd_sim_run_with': {'data', 'final', 'sink', 'stats'},
    'qd_speeds_derive': {'opts'},
    'qd_speeds_equilibria_find': {'opts', 'syms', 'vals'},
    'qd_speeds_eval': {'lambda', 'qd', 'ud'},
    'qd_speeds_modes_scan': {'opts'},
    'qd_stability_scan': {'opts', 'pguess'},
    'qd_steady_find': {'residual'},
    'qd_steady_find_all': {'pguess'},
    'qd_plot_pick_columns': {'ycols', 'phase'},
    'qd_sweep_map_column': {'measure'},
    'qd_sweep_needs': {'s', 'needs'},
    'qd_sweep_prepare': {'read', 'data'},
    'qd_sweep_run': {'data', 'progress'},
    'qd_sweep_run_one': {'stop'},
    'qd_sweep_set_lyap': {'lo'},
    'qd_sweep_setup_new': {'where'},
    'qd_state_named_range': {'m'},
    'qd_sweep_map_check': {'measure'},
    'qd_sweep_map_file': {'title'},
    'qd_sweep_hdf5_made': {'model', 'list'},
    'qd_lyap_setup_run': {'lo'},
    'qd_scene_setup_record': {'progress', 'data', 'stats'},
    'qd_symmetry_from_ops': {'R'},
    'qd_group_characters': {'R'},
    'qd_ufunc': {'args'},
    'qd_zvc_curves': {'syms', 'vals'},
    'qd_zvc_picture_make': {'syms', 'vals'},
}

# Functions whose result for a NULL argument is not the type's error value
# (documented in their header).
ANY_RESULT = {
    'qd_ctx_message',   # "" for a NULL context
    'qd_buf_str',       # "" for a NULL buffer
    'qd_status_str',
}

OPAQUE = set()          # filled from the headers: typedef struct X X;
FN_PTR = set()          # typedef R (*X)(...);


def strip(s):
    s = re.sub(r'/\*.*?\*/', ' ', s, flags=re.S)
    s = re.sub(r'//[^\n]*', ' ', s)
    return re.sub(r'^\s*#.*$', ' ', s, flags=re.M)


def split_params(s):
    out, depth, cur = [], 0, ''
    for ch in s:
        if ch == ',' and depth == 0:
            out.append(cur.strip())
            cur = ''
            continue
        depth += ch == '('
        depth -= ch == ')'
        cur += ch
    if cur.strip():
        out.append(cur.strip())
    return out


def parse_param(p):
    """(type, name, is_fnptr) of one parameter."""
    m = re.match(r'(.*)\(\s*\*\s*(\w+)\s*\)\s*\((.*)\)$', p)
    if m:
        return p, m.group(2), True
    if p.strip() == '...':
        return '...', '', False
    arr = re.search(r'\[\s*\w*\s*\]$', p)
    if arr:
        p = p[:arr.start()]
    m = re.match(r'(.*?)(\w+)$', p.strip())
    typ, name = m.group(1), m.group(2)
    if arr:
        typ += '*'
    return ' '.join(typ.replace('*', ' * ').split()), name, False


def parse_headers(root):
    funcs = []
    for path in sorted(glob.glob(os.path.join(root, 'include/qdot/*.h'))):
        text = strip(open(path).read())
        for m in re.finditer(r'typedef\s+struct\s+(\w+)\s+(\w+)\s*;', text):
            OPAQUE.add(m.group(2))
        for m in re.finditer(r'typedef\s+[\w\s*]+\(\s*\*\s*(\w+)\s*\)', text):
            FN_PTR.add(m.group(1))
        for m in re.finditer(r'QD_API\s+([^;{]*?)\s*;', text, flags=re.S):
            d = ' '.join(m.group(1).split())
            d = re.sub(r'__attribute__\s*\(\(.*\)\)\s*$', '', d).strip()
            m2 = re.match(r'(.*?)\b(qd_\w+)\s*\((.*)\)$', d)
            ret, name, params = m2.group(1).strip(), m2.group(2), m2.group(3)
            ps = [] if params.strip() in ('', 'void') else split_params(params)
            funcs.append((os.path.basename(path), ret, name, [parse_param(p) for p in ps]))
    return funcs


def base_type(typ):
    """'const qd_expr * const *' -> ('qd_expr', 2)"""
    words = [w for w in typ.replace('*', ' * ').split() if w not in ('const', 'struct')]
    stars = words.count('*')
    words = [w for w in words if w != '*']
    return ' '.join(words), stars


def is_pointer(typ, fnptr):
    return fnptr or '*' in typ or typ.split()[-1] in FN_PTR or typ == '...'


SCALAR_BUF = {'double': 'F.d', 'size_t': 'F.z', 'bool': 'F.b', 'int': 'F.i',
              'unsigned': 'F.u', 'long': 'F.l', 'uint64_t': 'F.u64',
              'qd_status': 'F.st', 'qd_diag': None}


def fixture(typ, name):
    """The valid value of a pointer argument of this type, or None."""
    bt, stars = base_type(typ)
    cast = '(' + typ + ')'
    if stars == 1:
        if bt == 'qd_ctx':
            return 'F.ctx'
        if bt == 'qd_model':
            return 'F.model'
        if bt == 'qd_eom':
            return 'F.eom'
        if bt in ('qd_sim', 'qd_plot', 'qd_prog'):
            return 'F.' + bt[3:]
        if bt == 'qd_expr':
            return 'F.q'
        if bt == 'qd_buf':
            return '&F.buf'
        if bt == 'char':
            return '"q"' if 'const' in typ else 'F.c'
        if bt in SCALAR_BUF and SCALAR_BUF[bt]:
            return SCALAR_BUF[bt]
        if bt not in OPAQUE and 'const' not in typ.split('*')[0] and bt.startswith('qd_') \
                and name in ('out', 'v', 'd', 'diag', 'err', 'stats', 'pt', 'dof', 'stat', 'res'):
            return cast + '(void *)F.blob'
        return None
    if stars == 2:
        if bt == 'qd_expr':
            return cast + 'F.e'
        if bt == 'char':
            return cast + 'F.names'
        if bt in SCALAR_BUF or bt in ('double', 'size_t'):
            return cast + '(void *)F.p'
    return None


def scalar_value(typ):
    t = re.sub(r'\bconst\b', '', typ).strip()
    if t in ('size_t', 'unsigned', 'int', 'long', 'uint64_t', 'double'):
        return '1'
    if t == 'bool':
        return 'false'
    return '(' + t + '){0}'


def calls(ret, name, params):
    """C statements calling name with each pointer argument NULL."""
    ptrs = [i for i, (t, n, f) in enumerate(params) if is_pointer(t, f)]
    if not ptrs:
        return []
    valid = []
    for t, n, f in params:
        if t == '...':
            valid.append(None)
        elif is_pointer(t, f):
            valid.append(None if f else fixture(t, n))
        else:
            valid.append(scalar_value(t))
    seen, out = set(), []
    for i in ptrs:
        if params[i][0] == '...' or params[i][1] in NULLABLE.get(name, ()):
            continue
        args = ['NULL' if (j == i or v is None) else v for j, v in enumerate(valid)
                if params[j][0] != '...']
        call = '%s(%s)' % (name, ', '.join(args))
        if call in seen:
            continue
        seen.add(call)
        out.append('    /* %s NULL */' % params[i][1])
        bt, stars = base_type(ret)
        if name in ANY_RESULT or ret == 'void':
            out.append('    %s;' % call if ret == 'void' else '    (void)%s;' % call)
        elif '*' in ret:
            out.append('    assert_null(%s);' % call)
        elif ret == 'qd_status':
            out.append('    assert_int_equal(QD_ERR_ARG, %s);' % call)
        elif ret in ('size_t', 'bool'):
            out.append('    assert_true(%s == 0);' % call)
        elif ret == 'double':
            out.append('    assert_true(isnan(%s));' % call)
        else:
            out.append('    (void)%s;' % call)
        out.append('    reset(&F);')
    return out


HEAD = '''/*
 * tests/api/test_null.c - every public function given NULL in each pointer
 * argument (issue 30): the documented error value, never a crash.
 *
 * Written by tests/api/gen_null_test.py from the headers in include/qdot/;
 * do not edit:
 * run `python3 tests/api/gen_null_test.py --root .` after changing a header
 * (the ctest api/check_null_coverage fails until then).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "qdot/qdot.h"
%INCLUDES%

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wformat"
#pragma GCC diagnostic ignored "-Wnonnull"
#pragma GCC diagnostic ignored "-Wformat-extra-args"
#endif

typedef struct fixture {
    qd_ctx *ctx;
    qd_model *model;
    qd_eom *eom;
    qd_sim *sim;
    qd_plot *plot;
    qd_prog *prog;
    const qd_expr *q;
    qd_buf buf;
    double d[512];
    size_t z[64];
    bool b[64];
    int i[64];
    unsigned u[64];
    long l[64];
    uint64_t u64[64];
    qd_status st[64];
    char c[512];
    const qd_expr *e[64];
    const char *names[64];
    void *p[64];
    max_align_t blob[1024];
} fixture;

static const char MODEL[] =
    "coordinates q\\n"
    "parameters m = 1, k = 1\\n"
    "T = m/2*q'^2\\n"
    "V = k/2*q^2\\n";

/* Fresh values for the next call: what a call wrote is gone, no error kept. */
static void reset(fixture *f)
{
    qd_ctx_clear_error(f->ctx);
    qd_buf_clear(&f->buf);
    memset(f->d, 0, sizeof f->d);
    memset(f->z, 0, sizeof f->z);
    memset(f->b, 0, sizeof f->b);
    memset(f->i, 0, sizeof f->i);
    memset(f->u, 0, sizeof f->u);
    memset(f->l, 0, sizeof f->l);
    memset(f->u64, 0, sizeof f->u64);
    memset(f->st, 0, sizeof f->st);
    memset(f->c, 0, sizeof f->c);
    memset(f->p, 0, sizeof f->p);
    memset(f->blob, 0, sizeof f->blob);
    for (size_t k = 0; k < 64; k++) {
        f->e[k] = f->q;
        f->names[k] = "q";
    }
}

static void setup(fixture *f)
{
    memset(f, 0, sizeof *f);
    f->ctx = qd_ctx_new();
    assert_non_null(f->ctx);
    f->model = qd_model_parse(f->ctx, MODEL, NULL);
    assert_non_null(f->model);
    f->eom = qd_eom_derive(f->ctx, f->model);
    assert_non_null(f->eom);
    f->q = qd_model_coord(f->model, 0);
    f->sim = qd_sim_new(f->ctx, f->model, f->eom);
    assert_non_null(f->sim);
    f->plot = qd_plot_new(f->ctx, 200, 200);
    assert_non_null(f->plot);
    f->prog = qd_prog_new(f->ctx, 1, &f->q, 1, &f->q);
    assert_non_null(f->prog);
    f->buf = (qd_buf)QD_BUF_INIT;
    reset(f);
}

static void teardown(fixture *f)
{
    qd_buf_free(&f->buf);
    qd_prog_free(f->prog);
    qd_plot_free(f->plot);
    qd_sim_free(f->sim);
    qd_eom_free(f->eom);
    qd_model_free(f->model);
    qd_ctx_free(f->ctx);
}
'''


def generate(root):
    funcs = parse_headers(root)
    by_header = {}
    for hdr, ret, name, params in funcs:
        by_header.setdefault(hdr, []).append((ret, name, params))
    out = [HEAD.replace('%INCLUDES%', '\n'.join('#include "qdot/%s"' % h for h in sorted(by_header)))]
    tests = []
    for hdr in sorted(by_header):
        tname = 'null_' + hdr[:-2]
        tests.append(tname)
        out.append('static void %s(void **state)\n{\n    (void)state;\n'
                   '    static fixture F;\n    setup(&F);' % tname)
        for ret, name, params in by_header[hdr]:
            body = calls(ret, name, params)
            out.append('    /* ---- %s */' % name)
            if body:
                out.extend(body)
            else:
                out.append('    /* no pointer argument */')
        out.append('    teardown(&F);\n}\n')
    out.append('int main(void)\n{\n    const struct CMUnitTest tests[] = {')
    out.extend('        cmocka_unit_test(%s),' % t for t in tests)
    out.append('    };\n    return cmocka_run_group_tests(tests, NULL, NULL);\n}')
    return '\n'.join(out) + '\n', funcs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--root', required=True)
    ap.add_argument('--check', action='store_true')
    a = ap.parse_args()
    text, funcs = generate(a.root)
    path = os.path.join(a.root, 'tests/api/test_null.c')
    if a.check:
        old = open(path).read() if os.path.exists(path) else ''
        if old != text:
            sys.stderr.write('%s is out of date with include/qdot/*.h (%d QD_API functions): '
                             'run python3 tests/api/gen_null_test.py --root .\n' % (path, len(funcs)))
            return 1
        undoc = sorted({h for h, _, _, _ in funcs
                        if 'NULL (issue 30)' not in open(os.path.join(a.root, 'include/qdot', h)).read()})
        if undoc:
            sys.stderr.write('headers without their NULL rule ("NULL (issue 30): ..."): %s\n'
                             % ', '.join(undoc))
            return 1
        print('%d public functions, each called with NULL in each pointer argument' % len(funcs))
        return 0
    with open(path, 'w') as f:
        f.write(text)
    return 0


if __name__ == '__main__':
    sys.exit(main())
