/* Telemetry samples of the paper's two-head pair (data/scenes/paper-fig2b.toml), for the probes
 * in C++ (flight_loop.hpp) and in C (c_interface.c). Decimal literals, the same bits on the
 * target and the host: 16 rows of the paper's orbit (a = 7280 km, e = 0.1) from perigee to
 * apogee at attitudes within 2 deg (their chords and phases from the sphere's closed form in
 * double), then corrupted rows as a link makes them (a grazing chord, a lost word, a radius
 * below the horizon sphere, chords out of range). Each row: the orbit radius (km), then the
 * chord and the phase of OH-1 and OH-2 (deg); a chord of -1 marks a lost word (NaN). */
#ifndef CONESCAN_FLIGHT_PAPER_SAMPLES_H
#define CONESCAN_FLIGHT_PAPER_SAMPLES_H

static const double paper_samples[][5] = {
    {6552, 137.955061, 1.5009139, 146.413805, -1.5009139},
    {6649.06667, 132.604452, 0.500001354, 133.186232, -0.500001354},
    {6746.13333, 128.982149, -0.500228877, 121.164635, 0.500228877},
    {6843.2, 116.782739, -1.5001015, 119.887489, 1.5001015},
    {6940.26667, 115.077917, 0.70015354, 109.293355, -0.70015354},
    {7037.33333, 103.559378, -0.300065808, 109.549344, 0.300065808},
    {7134.4, 103.063809, -1.30008798, 99.616925, 1.30008798},
    {7231.46667, 91.6237896, 0.900411932, 100.937272, -0.900411932},
    {7328.53333, 92.0782449, -0.100000271, 91.3349827, 0.100000271},
    {7425.6, 92.7849556, -1.10067033, 81.1521007, 1.10067033},
    {7522.66667, 81.6250282, 1.1000268, 84.0432824, -1.1000268},
    {7619.73333, 83.0973902, 0.100032772, 73.8162076, -0.100032772},
    {7716.8, 71.3273707, -0.900119404, 77.5017586, 0.900119404},
    {7813.86667, 73.5881315, 1.30017244, 67.1075609, -1.30017244},
    {7910.93333, 60.8022288, 0.300098315, 71.5543041, -0.300098315},
    {8008, 63.9709082, -0.700017057, 60.8835646, 0.700017057},
    {8005.43578, 64.5100683, 0.300011423, 0.05, 0}, /* OH-2 grazes */
    {8007.6, -1, 0.3, 359.98, 0},                   /* OH-1's word lost; OH-2 near 360 */
    {6000, 64.5, 0.3, 60.7, -0.3},                  /* radius below the horizon sphere */
    {8012, -4, 0.3, 400, -0.3},                     /* chords out of range */
};

enum { paper_sample_count = (int)(sizeof paper_samples / sizeof paper_samples[0]) };

#endif
