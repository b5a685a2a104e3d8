/* Catching the libraries' fatal errors in a test: a fatal handler (error.h) that keeps the
 * message and jumps back, so that a test can check that bad input is refused, and with what
 * message, and go on. What the failed call allocated is lost; tests do not mind.
 *
 *   STOPS_WITH(ok, call, text)   runs `call`; ok = 1 when it stopped with a fatal error whose
 *                                "where: message" contains text (the text caught is printed);
 *                                caught_where ("" when none) and caught_message keep the parts */
#ifndef TEST_CATCH_FATAL_H
#define TEST_CATCH_FATAL_H

#include <setjmp.h>
#include <stdio.h>
#include <string.h>

#include "error.h"

static jmp_buf caught_jump;
static char caught_where[4096], caught_message[4096];
static char caught_text[8200];   /* "where: message", or "message" */

static void keep_and_jump(const char *where, const char *message)
{
    snprintf(caught_where, sizeof caught_where, "%s", where ? where : "");
    snprintf(caught_message, sizeof caught_message, "%s", message);
    snprintf(caught_text, sizeof caught_text, "%s%s%s", caught_where, where ? ": " : "", message);
    longjmp(caught_jump, 1);
}

#define STOPS_WITH(ok, call, text)                                                      \
    do {                                                                                \
        caught_where[0] = caught_message[0] = caught_text[0] = '\0';                    \
        const dem_fatal_handler previous_handler = dem_set_fatal_handler(keep_and_jump); \
        if (setjmp(caught_jump) == 0) {                                                 \
            call;                                                                       \
            (ok) = 0;                                                                   \
        } else {                                                                        \
            (ok) = strstr(caught_text, (text)) != NULL;                                 \
            printf("      caught: %s\n", caught_text);                                  \
        }                                                                               \
        dem_set_fatal_handler(previous_handler);                                        \
    } while (0)

#endif
