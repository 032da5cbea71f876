/* shader.c: lesson 08's fragment shader, a real cost per fragment: the
 * face's Lambert colour times SHADER_OCTAVES octaves of value noise. */
#include "shader.h"

#include <math.h>

static double lattice(int32_t x, int32_t y) /* a hash of the corner, in [0, 1] */
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u;
    h ^= h >> 13;
    h *= 0x165667b1u;
    return ((h ^ (h >> 16)) & 0xffff) / 65535.0;
}

/* Value noise: lattice values blended with the smoothstep 3u^2 - 2u^3. */
static double value_noise(double x, double y)
{
    double fx = floor(x), fy = floor(y), u = x - fx, v = y - fy;
    int32_t i = (int32_t)fx, j = (int32_t)fy;
    u = u * u * (3 - 2 * u), v = v * v * (3 - 2 * v);
    double top = lattice(i, j) + (lattice(i + 1, j) - lattice(i, j)) * u;
    double bottom = lattice(i, j + 1) + (lattice(i + 1, j + 1) - lattice(i, j + 1)) * u;
    return top + (bottom - top) * v;
}

/* lit: the face's flat colour (shade.h: Lambert from its normal), darkened
 * by up to 30% by the noise, octaves of halving size and weight. */
Rgb shade_fragment(Rgb lit, int x, int y)
{
    double sum = 0, weight = 0, amplitude = 1, scale = 1.0 / 64;
    for (int k = 0; k < SHADER_OCTAVES; k++, amplitude *= 0.5, scale *= 2) {
        sum += amplitude * value_noise((x + 0.5) * scale, (y + 0.5) * scale);
        weight += amplitude;
    }
    double g = 0.7 + 0.3 * sum / weight;
    return (Rgb){(uint8_t)(lit.r * g + 0.5), (uint8_t)(lit.g * g + 0.5), (uint8_t)(lit.b * g + 0.5)};
}

