/*
 * src/plot/marks_draw.c - a panel's figure painted (qd_plot_add_mark's
 * springs, rods, arrows, pivots and walls), under its series.
 */
#include "plot_priv.h"

#include <math.h>

/* A spring: straight ends and a zigzag of 8 teeth between, a tenth of its
 * length wide (at most 7 px): a figure's spring as drawn in textbooks. */
static void draw_spring(const pen *cr, double ax, double ay, double bx, double by) {
    double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
    if (!(len > 0))
        return;
    double ux = dx / len, uy = dy / len, w = fmin(7, 0.1 * len), end = 0.15 * len;
    cr->op->move_to(cr->cv, ax, ay);
    cr->op->line_to(cr->cv, ax + end * ux, ay + end * uy);
    for (int t = 0; t < 16; t++) {
        double s = end + (len - 2 * end) * (t + 0.5) / 16, side = t % 2 ? -w : w;
        cr->op->line_to(cr->cv, ax + s * ux - side * uy, ay + s * uy + side * ux);
    }
    cr->op->line_to(cr->cv, bx - end * ux, by - end * uy);
    cr->op->line_to(cr->cv, bx, by);
    cr->op->stroke(cr->cv);
}

static void draw_arrow(const pen *cr, double ax, double ay, double bx, double by) {
    double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
    if (!(len > 1))
        return; /* a displacement under a pixel has no direction to show */
    double ux = dx / len, uy = dy / len, h = fmin(9, 0.4 * len);
    cr->op->move_to(cr->cv, ax, ay);
    cr->op->line_to(cr->cv, bx - h * ux, by - h * uy);
    cr->op->stroke(cr->cv);
    cr->op->move_to(cr->cv, bx, by);
    cr->op->line_to(cr->cv, bx - h * ux - 0.45 * h * uy, by - h * uy + 0.45 * h * ux);
    cr->op->line_to(cr->cv, bx - h * ux + 0.45 * h * uy, by - h * uy - 0.45 * h * ux);
    cr->op->fill(cr->cv);
}

/* A fixed support: a triangle under the point on a hatched ground line. */
static void draw_pivot(const pen *cr, double x, double y) {
    cr->op->move_to(cr->cv, x, y);
    cr->op->line_to(cr->cv, x - 8, y + 12);
    cr->op->line_to(cr->cv, x + 8, y + 12);
    cr->op->line_to(cr->cv, x, y);
    cr->op->stroke(cr->cv);
    cr->op->move_to(cr->cv, x - 13, y + 12);
    cr->op->line_to(cr->cv, x + 13, y + 12);
    for (int t = 0; t < 5; t++) {
        cr->op->move_to(cr->cv, x - 12 + 6 * t, y + 12);
        cr->op->line_to(cr->cv, x - 17 + 6 * t, y + 18);
    }
    cr->op->stroke(cr->cv);
}

/* A wall through (x, y) across the direction to (fx, fy): its line, and
 * the hatching on the side away from what it holds. */
static void draw_wall(const pen *cr, double x, double y, double fx, double fy) {
    double dx = fx - x, dy = fy - y, len = hypot(dx, dy);
    if (!(len > 0))
        return;
    double ux = dx / len, uy = dy / len, vx = -uy, vy = ux; /* u: towards it, v: along */
    cr->op->move_to(cr->cv, x - 13 * vx, y - 13 * vy);
    cr->op->line_to(cr->cv, x + 13 * vx, y + 13 * vy);
    for (int t = 0; t < 5; t++) {
        double s = -12 + 6 * t;
        cr->op->move_to(cr->cv, x + s * vx, y + s * vy);
        cr->op->line_to(cr->cv, x + (s - 5) * vx - 6 * ux, y + (s - 5) * vy - 6 * uy);
    }
    cr->op->stroke(cr->cv);
}

void qd__plot_draw_marks(const qd_plot *p, size_t k, const pen *cr) {
    static const unsigned colour[] = {0x8c8c8c, 0x404040, 0xd62728, 0x000000, 0x000000};
    static const double width[] = {1.5, 3, 1.5, 1.2, 1.2};
    cr->op->round_ends(cr->cv);
    for (size_t i = 0; i < p->nmarks; i++) {
        const qd__plot_mark *m = &p->marks[i];
        double ax, ay, bx, by;
        if (m->panel != k)
            continue;
        qd_plot_to_pixel(p, k, m->x0, m->y0, &ax, &ay);
        qd_plot_to_pixel(p, k, m->x1, m->y1, &bx, &by);
        cr->op->rgb(cr->cv, colour[m->kind]);
        cr->op->line_width(cr->cv, width[m->kind]);
        if (m->kind == QD_PLOT_SPRING)
            draw_spring(cr, ax, ay, bx, by);
        else if (m->kind == QD_PLOT_ARROW)
            draw_arrow(cr, ax, ay, bx, by);
        else if (m->kind == QD_PLOT_PIVOT)
            draw_pivot(cr, ax, ay);
        else if (m->kind == QD_PLOT_WALL)
            draw_wall(cr, ax, ay, bx, by);
    }
    /* the rods over the springs' ends, then the arrows' heads over both */
    for (size_t i = 0; i < p->nmarks; i++) {
        const qd__plot_mark *m = &p->marks[i];
        double ax, ay, bx, by;
        if (m->panel != k || m->kind != QD_PLOT_ROD)
            continue;
        qd_plot_to_pixel(p, k, m->x0, m->y0, &ax, &ay);
        qd_plot_to_pixel(p, k, m->x1, m->y1, &bx, &by);
        cr->op->rgb(cr->cv, colour[m->kind]);
        cr->op->line_width(cr->cv, width[m->kind]);
        cr->op->move_to(cr->cv, ax, ay);
        cr->op->line_to(cr->cv, bx, by);
        cr->op->stroke(cr->cv);
    }
}
