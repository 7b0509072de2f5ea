/*
 * tests/util/jsonwalk.h - reading a JSON document a printer wrote, for tests
 * that assert the numbers in it: a strict check of the grammar (RFC 8259)
 * and a walk to an object's member or an array's element, without building
 * a tree.  Every pointer is into the text itself, at the start of a value.
 */
#ifndef QT_JSONWALK_H
#define QT_JSONWALK_H

#include <stdbool.h>
#include <stddef.h>

/* The end of the JSON value at p (leading whitespace skipped), or NULL when
 * it is not one. */
const char *qt_json_skip(const char *p);
/* text is one JSON value and whitespace. */
bool qt_json_valid(const char *text);
/* The value of member key of the object at obj; NULL when obj is no object
 * or has no such member. */
const char *qt_json_get(const char *obj, const char *key);
/* Element i of the array at arr; NULL when arr is no array or is shorter. */
const char *qt_json_at(const char *arr, size_t i);
/* The number of elements of the array at arr (0 for no array). */
size_t qt_json_len(const char *arr);
/* The number at p (NaN when p is NULL or no number). */
double qt_json_num(const char *p);
/* The string at p is s (no escapes in s). */
bool qt_json_str_is(const char *p, const char *s);
/* The string at p copied to buf (cap bytes, escapes \" and \\ undone);
 * false when p is no string or it does not fit. */
bool qt_json_str(const char *p, char *buf, size_t cap);

#endif
