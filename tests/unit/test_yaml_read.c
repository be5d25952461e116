/* The YAML reader: values, ranges, unknown keys and their file:line:column. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene/yaml_read.h"

int main(void)
{
    gb_error err = {0};
    gb_yaml_doc doc;
    gb_ymap m, sub;
    double x = -1;
    long n = 0;

    const char *p = gb_test_file("yaml_ok.yaml", "# comment\na: 1.5e8\nsub:\n  n: 12\n  b: true\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_OK);
    CHECK(gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &m, &err) == GB_OK);
    CHECK(gb_ymap_number(&m, "a", GB_Y_REQUIRED | GB_Y_POSITIVE, &x, &err) == GB_OK);
    CHECK_NEAR(x, 1.5e8, 0);
    CHECK(gb_ymap_map(&m, "sub", GB_Y_REQUIRED, &sub, &err) == GB_OK);
    CHECK(gb_ymap_int(&sub, "n", GB_Y_REQUIRED, 1, 100, &n, &err) == GB_OK && n == 12);
    CHECK(gb_ymap_close(&sub, &err) == GB_EINPUT); /* b was never asked for */
    CHECK(strstr(err.msg, ":5:3: sub: unknown key 'b'") != NULL);
    x = 7;
    CHECK(gb_ymap_number(&m, "missing", GB_Y_OPTIONAL, &x, &err) == GB_OK && x == 7);
    CHECK(gb_ymap_number(&m, "missing", GB_Y_REQUIRED, &x, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, "missing key 'missing'") != NULL);
    gb_yaml_free(&doc);

    p = gb_test_file("yaml_tiny.yaml", "a: 8.8e-317\nb: 1e309\n"); /* a subnormal reads back; overflow does not */
    CHECK(gb_yaml_load(p, &doc, &err) == GB_OK);
    gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &m, &err);
    CHECK(gb_ymap_number(&m, "a", 0, &x, &err) == GB_OK && x == 8.8e-317);
    CHECK(gb_ymap_number(&m, "b", 0, &x, &err) == GB_EINPUT && strstr(err.msg, ":2:4: b: expected a finite number"));
    gb_yaml_free(&doc);

    p = gb_test_file("yaml_bad.yaml", "a: -3\nb: .nan\nc: \"12\"\nd: 1.5x\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_OK);
    gb_ymap_open(&doc, fy_document_root(doc.fyd), "", &m, &err);
    CHECK(gb_ymap_number(&m, "a", GB_Y_POSITIVE, &x, &err) == GB_EINPUT && strstr(err.msg, ":1:4:"));
    CHECK(gb_ymap_number(&m, "b", 0, &x, &err) == GB_EINPUT && strstr(err.msg, ":2:4:"));
    CHECK(gb_ymap_number(&m, "c", 0, &x, &err) == GB_EINPUT && strstr(err.msg, "quoted"));
    CHECK(gb_ymap_number(&m, "d", 0, &x, &err) == GB_EINPUT && strstr(err.msg, ":4:4:"));
    gb_yaml_free(&doc);

    p = gb_test_file("yaml_syntax.yaml", "a: [1, 2\nb: 3\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, "syntax error") != NULL);
    CHECK(gb_yaml_load("/nonexistent/scene.yaml", &doc, &err) == GB_EINPUT);

    /* "did you mean": a typo of a long key (a swap, a letter missed, the case) is named at its
     * own line; of a short key it is not (kn and kt, de1 and de2 are different keys) */
    p = gb_test_file("yaml_typo.yaml", "friciton_deg: 25\nkt: 7\nAccuracy: 1\nde2: 0\nmax_iteration: 5\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_OK);
    gb_ymap_open(&doc, fy_document_root(doc.fyd), "m", &m, &err);
    CHECK(gb_ymap_number(&m, "friction_deg", GB_Y_REQUIRED, &x, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, ":1:1: missing key 'm.friction_deg' (found 'friciton_deg': did you mean 'friction_deg'?)"));
    CHECK(gb_ymap_number(&m, "accuracy", GB_Y_REQUIRED, &x, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, ":3:1: missing key 'm.accuracy' (found 'Accuracy': did you mean 'accuracy'?)"));
    CHECK(gb_ymap_number(&m, "kn", GB_Y_REQUIRED, &x, &err) == GB_EINPUT && !strstr(err.msg, "did you mean"));
    CHECK(gb_ymap_number(&m, "de1", GB_Y_REQUIRED, &x, &err) == GB_EINPUT && !strstr(err.msg, "did you mean"));
    CHECK(gb_ymap_number(&m, "kt", 0, &x, &err) == GB_OK && gb_ymap_number(&m, "de2", 0, &x, &err) == GB_OK);
    CHECK(gb_ymap_number(&m, "max_iterations", 0, &x, &err) == GB_OK);
    CHECK(gb_ymap_close(&m, &err) == GB_EINPUT); /* the first key unread: friciton_deg */
    CHECK(strstr(err.msg, "unknown key 'friciton_deg'; did you mean 'friction_deg'? expected one of:"));
    gb_yaml_free(&doc);
    static const char *const stages[] = {"isotropic", "strain"};
    CHECK(gb_yaml_closest("strian", 6, stages, 2) == 1 && gb_yaml_closest("shear", 5, stages, 2) == -1);

    /* UTF-8 is checked before libfyaml, which looped forever on a directive with a byte that is not
     * (fuzz/regress/scene): the place of the bad byte; a character split across two reads is fine */
    p = gb_test_file("yaml_latin1.yaml", "a: 1\n%YAML\xe9\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_EINPUT);
    CHECK(strstr(err.msg, ":2:6: byte 0xe9 is not UTF-8 text") != NULL);
    p = gb_test_file("yaml_overlong.yaml", "%\xe0\x9b\x9e\n"); /* a 3-byte form of a 2-byte character: it hung too */
    CHECK(gb_yaml_load(p, &doc, &err) == GB_EINPUT && strstr(err.msg, ":1:2: byte 0xe0") != NULL);
    p = gb_test_file("yaml_surrogate.yaml", "%\xed\xa0\x80\n");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_EINPUT && strstr(err.msg, ":1:2: byte 0xed") != NULL);
    p = gb_test_file("yaml_truncated.yaml", "a: caf\xc3");
    CHECK(gb_yaml_load(p, &doc, &err) == GB_EINPUT && strstr(err.msg, ":1:7: byte 0xc3") != NULL);
    /* and YAML's characters only (YAML 1.2, section 5.1): libfyaml 0.7 wrote through a null
     * pointer on this text with a NUL (fuzz/regress/state); C0 and C1 controls, DEL, U+FFFE are
     * refused where they stand, tab, NEL and the astral planes are text */
#define BYTES(s) s, sizeof(s) - 1
    static const struct {
        const char *bytes;
        size_t n;
        const char *where; /* NULL: accepted */
    } chars[] = {{BYTES("? a:\t\0\n"), ":1:6: character U+0000 is not allowed"},
                 {BYTES("a: 1\nb: \x0c\n"), ":2:4: character U+000C"},
                 {BYTES("a: \x7f\n"), ":1:4: character U+007F"},
                 {BYTES("a: x\xc2\x80\n"), ":1:5: character U+0080"},
                 {BYTES("a: \xef\xbf\xbe\n"), ":1:4: character U+FFFE"},
                 {BYTES("a: \t\xc2\x85\xf0\x9f\x98\x80\r\n"), NULL}};
    for (size_t k = 0; k < sizeof chars / sizeof chars[0]; k++) {
        const char *q = gb_test_file("yaml_control.yaml", "");
        FILE *f = fopen(q, "wb");
        CHECK(f && fwrite(chars[k].bytes, 1, chars[k].n, f) == chars[k].n && !fclose(f));
        gb_status st = gb_yaml_load(q, &doc, &err);
        CHECK(chars[k].where ? st == GB_EINPUT && strstr(err.msg, chars[k].where) : st == GB_OK);
        gb_yaml_free(&doc);
        st = gb_yaml_load_text(chars[k].bytes, chars[k].n, "text", &doc, &err);
        CHECK(chars[k].where ? st == GB_EINPUT && strstr(err.msg, chars[k].where) : st == GB_OK);
        gb_yaml_free(&doc);
    }
    static char big[8200];
    for (int shift = 0; shift < 4; shift++) {
        memset(big, 0, sizeof big);
        memcpy(big, "a: ", 3);
        memset(big + 3, 'x', 4092 - 3 + (size_t)shift);
        strcat(big, "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\n"); /* e acute, euro, an emoji across offset 4096 */
        CHECK(gb_yaml_load(gb_test_file("yaml_split.yaml", big), &doc, &err) == GB_OK);
        gb_yaml_free(&doc);
    }
    TEST_END();
}
