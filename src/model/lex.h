/*
 * src/model/lex.h - tokens of the model language.
 *
 * Newlines end statements except inside brackets, so a long expression may
 * continue on the next line while a bracket is open.  '#' starts a comment.
 */
#ifndef QD_MODEL_LEX_H
#define QD_MODEL_LEX_H

#include <stdbool.h>
#include <stddef.h>

typedef enum tk_kind {
    TK_EOF, TK_NEWLINE, TK_IDENT, TK_NUMBER,
    TK_LPAREN, TK_RPAREN, TK_LBRACK, TK_RBRACK,
    TK_COMMA, TK_EQ, TK_PLUS, TK_MINUS, TK_STAR, TK_SLASH, TK_CARET,
    TK_PRIME, TK_DOT, TK_COLON, TK_GE, TK_LE, TK_BAD
} tk_kind;

typedef struct token {
    tk_kind kind;
    size_t off, len;
} token;

#define LEX_MAX_DEPTH 256

typedef struct lexer {
    const char *src;
    size_t pos;
    token tok;                        /* the current token */
    size_t open[LEX_MAX_DEPTH];       /* offsets of the open brackets */
    int depth;
    bool too_deep;
} lexer;

void qd__mdl_lex_init(lexer *lx, const char *src);
void qd__mdl_lex_next(lexer *lx);             /* advance lx->tok */
bool qd__mdl_lex_is(const lexer *lx, const char *word); /* current token is this identifier */
const char *qd__mdl_lex_tk_name(tk_kind k);       /* "')'", "a number", ... for messages */

#endif
