/*
 * src/lyap/render.c - the flow Jacobian printed (qdot/lyapunov.h): the
 * options a flow run takes from a simulation's (qd_flow_sim_opts), the
 * names of the state and of the columns of the Jacobian's rows
 * (qd_flow_state_name, qd_flow_column_name), and a qd_flow as text
 * (qd_flow_print: the matrix, det against Liouville, the symplectic
 * error, the Floquet multipliers and the closure) or as members of a JSON
 * object (qd_flow_json).  `qdot simulate --variational` prints these.
 */
#include "qdot/lyapunov.h"
#include "qdot/json.h"
#include "../base/args.h"

#include <math.h>

qd_status qd_flow_sim_opts(const qd_sim_opts *in, qd_sim_opts *out) {
    QD_ARGS(QD_ERR_ARG, in && out);
    *out = *in;
    if (out->method != QD_SIM_DOPRI5 && out->method != QD_SIM_DOP853) {
        out->method = QD_SIM_DOP853;
        out->fixed = false;
    }
    return QD_OK;
}

qd_status qd_flow_state_name(const qd_eom *e, size_t i, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, e && out);
    if (i >= 2 * e->n)
        return QD_ERR_ARG;
    qd_buf_puts(out, qd_expr_name(e->q[i % e->n]));
    if (i >= e->n)
        qd_buf_puts(out, "'");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_flow_column_name(const qd_eom *e, size_t k, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, e && out);
    size_t d = 2 * e->n;
    if (k >= 1 + d + d * d)
        return QD_ERR_ARG;
    if (k == 0) {
        qd_buf_puts(out, "t");
        return out->failed ? QD_ERR_NOMEM : QD_OK;
    }
    if (k <= d)
        return qd_flow_state_name(e, k - 1, out);
    size_t c = k - 1 - d; /* column j of Phi, row i: c = j d + i */
    qd_buf_puts(out, "d");
    qd_flow_state_name(e, c % d, out);
    qd_buf_puts(out, "/d");
    qd_flow_state_name(e, c / d, out);
    qd_buf_puts(out, "0");
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

static bool flow_ok(const qd_flow *f) {
    return f && f->d > 0 && f->phi && f->mult_re && f->mult_im && (!f->hamiltonian || f->phi_c);
}

qd_status qd_flow_print(const qd_flow *f, double period, const char *prefix, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, out);
    if (!flow_ok(f))
        return QD_ERR_ARG;
    const char *pre = prefix ? prefix : "";
    size_t d = f->d;
    qd_buf_puts(out, pre);
    qd_buf_printf(out, "flow Jacobian d(q, q')(t_end)/d(q, q')(t0), det %.10g (Liouville "
                       "exp(int tr J) %.10g)", f->det, exp(f->trace_integral));
    if (f->hamiltonian)
        qd_buf_printf(out, ", symplectic error in (q, p) %.3g", f->symplectic_error);
    qd_buf_puts(out, "\n");
    for (size_t i = 0; i < d; i++) {
        qd_buf_puts(out, pre);
        qd_buf_puts(out, " ");
        for (size_t k = 0; k < d; k++)
            qd_buf_printf(out, " % .10g", f->phi[i * d + k]);
        qd_buf_puts(out, "\n");
    }
    qd_buf_puts(out, pre);
    qd_buf_puts(out, period > 0 ? "Floquet multipliers:" : "eigenvalues:");
    for (size_t i = 0; i < d; i++)
        qd_buf_printf(out, " %.10g%+.10gi", f->mult_re[i], f->mult_im[i]);
    qd_buf_puts(out, period > 0 ? "\n" : " (give the period T for a periodic orbit)\n");
    if (period > 0) {
        qd_buf_puts(out, pre);
        qd_buf_printf(out, "closure max |y(t0 + T) - y(t0)| = %.3g%s\n", f->closure,
                      f->closure > QD_FLOW_CLOSURE_TOL ? ": the orbit is not periodic with this T"
                                                       : "");
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_flow_json(qd_json *j, const qd_flow *f, const qd_eom *e, qd_sim_method method,
                       double period) {
    QD_ARGS(QD_ERR_ARG, j && j->out && e);
    if (!flow_ok(f) || f->d != 2 * e->n)
        return QD_ERR_ARG;
    size_t d = f->d;
    qd_json_key(j, "variational");
    qd_json_begin_object(j);
    qd_json_key(j, "method");
    qd_json_string(j, qd_sim_method_name(method));
    qd_json_key(j, "state");
    qd_json_begin_array(j);
    qd_buf name = QD_BUF_WITH(j->out->alloc);
    for (size_t i = 0; i < d; i++) {
        qd_buf_clear(&name);
        qd_flow_state_name(e, i, &name);
        qd_json_string(j, qd_buf_str(&name));
    }
    if (name.failed)
        j->out->failed = true;
    qd_buf_free(&name);
    qd_json_end_array(j);
    qd_json_end_object(j);
    qd_json_matrix(j, "flow_jacobian", d, d, f->phi);
    qd_json_key(j, "flow_det");
    qd_json_number(j, f->det);
    qd_json_key(j, "liouville_det"); /* exp(integral of tr J) */
    qd_json_number(j, exp(f->trace_integral));
    qd_json_key(j, "hamiltonian");
    qd_json_bool(j, f->hamiltonian);
    if (f->hamiltonian)
        qd_json_matrix(j, "flow_jacobian_canonical", d, d, f->phi_c);
    qd_json_key(j, "symplectic_error");
    if (f->hamiltonian)
        qd_json_number(j, f->symplectic_error);
    else
        qd_json_null(j);
    qd_json_key(j, "multipliers");
    qd_json_begin_array(j);
    for (size_t i = 0; i < d; i++) {
        qd_json_begin_array(j);
        qd_json_number(j, f->mult_re[i]);
        qd_json_number(j, f->mult_im[i]);
        qd_json_end_array(j);
    }
    qd_json_end_array(j);
    qd_json_key(j, "period");
    if (period > 0)
        qd_json_number(j, period);
    else
        qd_json_null(j);
    qd_json_key(j, "closure");
    qd_json_number(j, f->closure);
    if (period > 0)
        qd_json_matrix(j, "monodromy", d, d, f->phi);
    if (j->out->failed || j->nomem)
        return QD_ERR_NOMEM;
    return j->failed ? QD_ERR_NUMERIC : QD_OK;
}
