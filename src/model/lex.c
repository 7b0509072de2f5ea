/* src/model/lex.c - see lex.h. */
#include "lex.h"

#include <ctype.h>
#include <string.h>

void qd__mdl_lex_init(lexer *lx, const char *src) {
    memset(lx, 0, sizeof *lx);
    lx->src = src;
    qd__mdl_lex_next(lx);
}

/* The bytes of the line end at s: "\n", "\r\n" or a lone "\r" (old Mac
 * files); 0 when s is not at one. */
static size_t line_end(const char *s) {
    if (s[0] == '\n')
        return 1;
    if (s[0] == '\r')
        return s[1] == '\n' ? 2 : 1;
    return 0;
}

static void skip_blanks(lexer *lx) {
    const char *s = lx->src;
    for (;;) {
        char c = s[lx->pos];
        size_t eol = line_end(s + lx->pos);
        if (c == ' ' || c == '\t' || (eol && lx->depth > 0))
            lx->pos += eol ? eol : 1;
        else if (c == '\\' && line_end(s + lx->pos + 1))
            lx->pos += 1 + line_end(s + lx->pos + 1); /* an explicit line continuation */
        else if (c == '#')
            while (s[lx->pos] && s[lx->pos] != '\n' && s[lx->pos] != '\r')
                lx->pos++;
        else
            return;
    }
}

static size_t number_len(const char *s) {
    size_t i = 0;
    while (isdigit((unsigned char)s[i]))
        i++;
    if (s[i] == '.' && isdigit((unsigned char)s[i + 1])) {
        i++;
        while (isdigit((unsigned char)s[i]))
            i++;
    } else if (s[i] == '.' && i > 0 && !isalpha((unsigned char)s[i + 1]) && s[i + 1] != '.') {
        i++; /* "2." (but "0..l" is 0, '.', '.', l: a field's interval) */
    }
    if ((s[i] == 'e' || s[i] == 'E') &&
        (isdigit((unsigned char)s[i + 1]) ||
         ((s[i + 1] == '+' || s[i + 1] == '-') && isdigit((unsigned char)s[i + 2])))) {
        i += 2;
        while (isdigit((unsigned char)s[i]))
            i++;
    }
    return i;
}

static tk_kind punct(lexer *lx, char c) {
    switch (c) {
    case '(': case '[':
        if (lx->depth < LEX_MAX_DEPTH)
            lx->open[lx->depth] = lx->pos;
        else
            lx->too_deep = true;
        lx->depth++;
        return c == '(' ? TK_LPAREN : TK_LBRACK;
    case ')': case ']':
        if (lx->depth > 0)
            lx->depth--;
        return c == ')' ? TK_RPAREN : TK_RBRACK;
    case ',': return TK_COMMA;
    case '=': return TK_EQ;
    case '+': return TK_PLUS;
    case '-': return TK_MINUS;
    case '*': return TK_STAR;
    case '/': return TK_SLASH;
    case '^': return TK_CARET;
    case '\'': return TK_PRIME;
    case '.': return TK_DOT;
    case ':': return TK_COLON;
    case '\n': return TK_NEWLINE;
    default: return TK_BAD;
    }
}

void qd__mdl_lex_next(lexer *lx) {
    skip_blanks(lx);
    const char *s = lx->src + lx->pos;
    token t = {TK_EOF, lx->pos, 0};
    if (!*s) {
        lx->tok = t;
        return;
    }
    if (isalpha((unsigned char)*s) || *s == '_') {
        size_t n = 1;
        while (isalnum((unsigned char)s[n]) || s[n] == '_')
            n++;
        t.kind = TK_IDENT;
        t.len = n;
    } else if (isdigit((unsigned char)*s) ||
               (*s == '.' && isdigit((unsigned char)s[1]) && !(lx->pos > 0 && s[-1] == '.'))) {
        t.kind = TK_NUMBER;
        t.len = number_len(s);
        if (t.len == 0) /* ".5" */
            t.len = 1 + number_len(s + 1);
    } else if (s[0] == '*' && s[1] == '*') {
        t.kind = TK_CARET; /* Python's power, accepted as ^ */
        t.len = 2;
    } else if ((s[0] == '>' || s[0] == '<') && s[1] == '=') {
        t.kind = s[0] == '>' ? TK_GE : TK_LE; /* a unilateral contact's gap */
        t.len = 2;
    } else if (line_end(s)) {
        t.kind = TK_NEWLINE; /* one token for a \r\n */
        t.len = line_end(s);
    } else {
        t.kind = punct(lx, *s);
        t.len = 1;
        if (t.kind == TK_BAD && ((unsigned char)*s & 0x80)) /* one whole UTF-8 character */
            while (((unsigned char)s[t.len] & 0xC0) == 0x80)
                t.len++;
    }
    lx->pos += t.len;
    lx->tok = t;
}

bool qd__mdl_lex_is(const lexer *lx, const char *word) {
    size_t n = strlen(word);
    return lx->tok.kind == TK_IDENT && lx->tok.len == n &&
           memcmp(lx->src + lx->tok.off, word, n) == 0;
}

const char *qd__mdl_lex_tk_name(tk_kind k) {
    static const char *const names[] = {
        "the end of the file", "the end of the line", "a name", "a number",
        "'('", "')'", "'['", "']'", "','", "'='", "'+'", "'-'", "'*'", "'/'", "'^'",
        "a prime (')", "'.'", "':'", "'>='", "'<='", "an unexpected character",
    };
    return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "?";
}
