/* A C program using the installed mcmd package: MCMDTerrain() from scratch
 * and around a sketch band, and its error contract.
 * Usage: make_terrain out.tif
 * Writes a 257x257 terrain (RS=300m) to out.tif; checks that a sketch's
 * known cells are kept, that two runs give the same cells, and that a bad
 * option fails with a message. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cpl_error.h"
#include "cpl_string.h"
#include "gdal.h"
#include "mcmd_gdal.h"

enum { N = 257 };

static int fail(const char *what) {
  fprintf(stderr, "make_terrain: %s\n", what);
  return 1;
}

static GDALDatasetH memory(void) {
  return GDALCreate(GDALGetDriverByName("MEM"), "", N, N, 1, GDT_Float32, NULL);
}

static int read_band(GDALDatasetH ds, float *cells) {
  return GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, N, N, cells, N, N, GDT_Float32, 0, 0) == CE_None;
}

int main(int argc, char **argv) {
  if (argc != 2) return fail("usage: make_terrain out.tif");
  GDALAllRegister();
  static float a[N * N], b[N * N], sketch[N * N];

  /* From scratch, twice: the same cells. */
  char **options = CSLSetNameValue(NULL, "RS", "300m");
  options = CSLSetNameValue(options, "SEED", "7");
  GDALDatasetH first = memory(), second = memory();
  if (MCMDTerrain(GDALGetRasterBand(first, 1), NULL, options, GDALDummyProgress, NULL) != CE_None)
    return fail(CPLGetLastErrorMsg());
  if (MCMDTerrain(GDALGetRasterBand(second, 1), NULL, options, NULL, NULL) != CE_None) return fail("second run");
  if (!read_band(first, a) || !read_band(second, b)) return fail("read back");
  float lo = a[0], hi = a[0];
  for (int i = 0; i < N * N; ++i) {
    if (!isfinite(a[i]) || a[i] != b[i]) return fail("not finite, or not the same twice");
    lo = a[i] < lo ? a[i] : lo;
    hi = a[i] > hi ? a[i] : hi;
  }
  if (hi - lo < 100) return fail("flat");
  GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName("GTiff"), argv[1], first, FALSE, NULL, NULL, NULL);
  if (!out) return fail("cannot write the output");
  GDALClose(out);

  /* Around a sketch: white (255) unknown, a grey diagonal kept. */
  GDALDatasetH sk = GDALCreate(GDALGetDriverByName("MEM"), "", N, N, 1, GDT_Byte, NULL);
  for (int i = 0; i < N * N; ++i) sketch[i] = (i % N == i / N) ? (float)(20 + (i % N) % 200) : 255.0f;
  if (GDALRasterIO(GDALGetRasterBand(sk, 1), GF_Write, 0, 0, N, N, sketch, N, N, GDT_Float32, 0, 0) != CE_None)
    return fail("cannot write the sketch");
  options = CSLSetNameValue(options, "RS", "0.2");
  if (MCMDTerrain(GDALGetRasterBand(second, 1), GDALGetRasterBand(sk, 1), options, NULL, NULL) != CE_None)
    return fail(CPLGetLastErrorMsg());
  if (!read_band(second, b)) return fail("read back");
  for (int k = 0; k < N; ++k)
    if (b[k * N + k] != sketch[k * N + k]) return fail("a known sketch cell changed");

  /* A bad option: CE_Failure and a message, nothing written. */
  char **bad = CSLSetNameValue(NULL, "SCHEME", "hexagon");
  CPLPushErrorHandler(CPLQuietErrorHandler);
  const CPLErr err = MCMDTerrain(GDALGetRasterBand(first, 1), NULL, bad, NULL, NULL);
  CPLPopErrorHandler();
  if (err != CE_Failure || !strstr(CPLGetLastErrorMsg(), "SCHEME=hexagon")) return fail("a bad option was accepted");
  if (!read_band(first, b)) return fail("read back");
  if (memcmp(a, b, sizeof a) != 0) return fail("a failed call wrote cells");

  CSLDestroy(options);
  CSLDestroy(bad);
  GDALClose(first);
  GDALClose(second);
  GDALClose(sk);
  printf("mcmd %s: MCMDTerrain made a %dx%d terrain (%.1f .. %.1f) and kept the sketch\n", MCMDVersion(), N, N, lo, hi);
  return 0;
}
