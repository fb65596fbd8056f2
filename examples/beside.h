/* beside.h - where the examples write their outputs by default: beside the
 * program (a CMake build's programs are in the build tree), never into the
 * source tree. */
#ifndef MIST_EXAMPLES_BESIDE_H
#define MIST_EXAMPLES_BESIDE_H
#include <stddef.h>
#include <string.h>

/* DIR/NAME where the program is DIR/PROGRAM, else NAME (the working directory) */
static const char *beside_program(char *buf, size_t size, const char *argv0, const char *name)
{
    const char *slash = argv0 ? strrchr(argv0, '/') : NULL;
    size_t dir = slash ? (size_t)(slash - argv0) + 1 : 0;
    if (dir + strlen(name) + 1 > size) return name;
    memcpy(buf, argv0, dir);
    strcpy(buf + dir, name);
    return buf;
}

#endif
