//ST::IF SURFACE
  // The ray's first dense samples take the light inside their texel (st_surfaceChange).
  // The first finds where its surface's matter begins; the second, where it follows the
  // first a step later, shows the matter after it. A second that does not follow lies in
  // other matter and keeps the light the loop gave it: its own search would double the
  // code llvmpipe compiles for this exit, held in host memory (docs/rendering.md).
  if (st_surfaceCount > 0)
    {
    g_fragColor.rgb += st_surfaceChange(0);
    }
  if (st_surfaceCount > 1 && st_surfaceAt[1] < st_surfaceAt[0] + 1.5)
    {
    g_fragColor.rgb += st_surfaceChange(1);
    }
//ST::ENDIF
