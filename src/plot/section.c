/*
 * src/plot/section.c - the coordinate a Poincare section's plot shows by
 * default (qd_plot_section_phase, qdot/plot.h): the section fixes the
 * coordinates it names, so the plot shows the first one it does not name.
 */
#include "qdot/plot.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdbool.h>
#include <string.h>

/* The name is a word of text: not part of a longer name (letters, digits,
 * '_' either side). */
static bool names_word(const char *text, const char *name) {
    size_t len = strlen(name);
    if (!len)
        return false;
    for (const char *s = text; (s = strstr(s, name)); s += len) {
        bool before = s > text && (isalnum((unsigned char)s[-1]) || s[-1] == '_');
        bool after = isalnum((unsigned char)s[len]) || s[len] == '_';
        if (!before && !after)
            return true;
    }
    return false;
}

const char *qd_plot_section_phase(const char *section, const char *const *names, size_t ndof) {
    QD_ARGS(NULL, section && (names || !ndof));
    for (size_t j = 0; j < ndof; j++)
        if (names[1 + j] && !names_word(section, names[1 + j]))
            return names[1 + j];
    return ndof ? names[1] : NULL;
}
