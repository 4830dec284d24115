
//============================================================================
// Scatterer-template illumination (ScattererTemplate; Lee, Kwon, Shin 2016).
// Per-sample mode (PERSAMPLE, the paper's local photon test): photon offsets
// are in template radii; st_toTex* turn them into texture coordinates (they
// include the template radius and the volume's transform). The transport mode
// (TRANSPORT) reads the light transport volume (vtkScattererTransportVolume)
// and needs nothing from this file.
//============================================================================
// Material arrays are sized by the mapper's limit and light arrays by a few
// fixed slot counts (1, 2, 4, 6: the light count rounded up); loops run to the
// scene's counts (st_lightCount, st_materialCount uniforms). Adding a light or a
// material then changes uniforms only, or the text among four light variants,
// so it compiles few new programs (VTK keeps every program it compiled for the
// window's lifetime). One slot per light keeps the photon loop's per-light
// values in registers: six slots for one light made the per-sample mode 2x
// slower on llvmpipe.
#define ST_LIGHT_SLOTS @LIGHT_SLOTS@
#define ST_MAX_MATERIALS @MAX_MATERIALS@

//ST::IF TRANSPORT
// The display of the received light (st_compressHighlights): it is shown at st_exposure
// of its level, and above st_knee compressed smoothly toward 1 instead of clipping.
// - st_exposure 0.8 leaves headroom for what multiple scattering adds on top of the
//   light that arrives: at 1, 14 % of the CT head's drawn pixels had their red at the
//   display's ceiling (the reference: 0.02 %), and the lit bone turned paler wherever
//   light was added. At 0.8 the defaults of all five accuracy scenes came closer to the
//   Monte Carlo reference in RMSE than at 0.9 and 1.0, the CT head's mean lit luminance
//   is 0.92x stock Phong's (2026-12-07), and an unoccluded face toward a light (received
//   light 1) shows 0.8 of its colour, thin or dense (a dense one's single scattering's
//   share less, as it falls inside the face: st_surfaceChange) (docs/brightness.md,
//   docs/accuracy.md).
// - st_knee 0.85: measured closer to the reference than 0.7, which compressed more of the
//   lit range.
const float st_exposure = 0.8;
const float st_knee = 0.85;
mat4 st_toTransport; // ray position -> light texture, set once per ray (shading init)

// The light transport volume at ray position `dataPos`: the light the point receives,
// summed over the lights (global shadows, template in-scattering, multiple scattering,
// VTK's ambient term occluded like the light): one texture read. Its texels hold their
// light times their weight and the weight in alpha (dense interior texels weigh little:
// scatterer_transport_gather.glsl), so the light is the ratio of the two interpolations
// (no weight is 0; the floor only keeps a texture never drawn from dividing 0 by 0).
vec3 st_transportRead(vec3 dataPos)
{
  vec4 weighted = texture3D(st_transport, (st_toTransport * vec4(dataPos, 1.0)).xyz);
  return weighted.rgb / max(weighted.a, 1.0e-6);
}

// The light shown: the received light times st_exposure, and above st_knee compressed
// smoothly toward 1 instead of clipping (multiple scattering makes dense, white
// materials glow well above what a display shows); below it kept as it is.
vec3 st_compressHighlights(vec3 received)
{
  vec3 light = st_exposure * received;
  return mix(light, st_knee + (light - st_knee) / (1.0 + (light - st_knee) / (1.0 - st_knee)),
    step(vec3(st_knee), light));
}

// The light a sample takes from a transport read. With VTK's gradient shading on (Shade),
// the read is a visibility: the shaded colour (which already carries the lights'
// intensities, clamped to 1 by VTK) times the read over an unoccluded white sample's light
// (the shading divides by it). The knee compresses that ratio, not the
// read: compressed before the division, the ratio fell as 1 / intensity, and a brighter
// light drew a darker picture (intensity 1000: black); not compressed at all, the
// multiple scattering's glow above 1 pushed the shaded colour into the display's clamp
// (an orange, flat crown under ParaView's light kit).
vec3 st_shownLight(vec3 received)
{
//ST::IF PHONG
  return st_compressHighlights(received * st_unlitNorm) / st_unlitNorm;
//ST::ELSE
  return st_compressHighlights(received);
//ST::ENDIF
}
//ST::IF GROUPED

// Samples that share a light read: the light at the far end of the group, read by
// its first sample (at the ray's start by the shading init). Below st_lightFloor the
// geometric interpolation takes the light as that floor (no division by zero).
vec3 st_lightEnd;
const vec3 st_lightFloor = vec3(1.0e-4);

// The factor from one sample's light to the next's in a group: the ratio r of the
// group's two reads to the power 1/n, n = @LIGHT_STRIDE@. For the strides
// lightReadStride picks (2 and 4) by square roots, exactly: pow(r, 1/n) is
// exp2(log2(r) / n), which llvmpipe evaluates by polynomials in every lane
// (docs/rendering.md, "Fewer light reads"). The condition is a constant.
vec3 st_strideRoot(vec3 r)
{
  const int n = @LIGHT_STRIDE@;
  return n == 4 ? sqrt(sqrt(r)) : (n == 2 ? sqrt(r) : pow(r, vec3(1.0 / float(n))));
}
//ST::ENDIF
//ST::IF SURFACE

// The light inside a dense texel, along the brightest light (docs/model.md, "The light
// inside a dense texel"). A transport texel holds the light entering it, at its face
// toward the light; in dense matter (bone: several mean free paths a texel) the light
// falls by far more than that inside it. Single scattering in a semi-infinite medium lit
// at cosine mu_l and seen at mu_v reflects, per unit of light (Chandrasekhar 1960,
// Radiative Transfer, ch. 3; isotropic scattering),
//   omega/4 mu_l / (mu_l + mu_v),
// which a ray's samples composite only if each takes its own attenuation toward the light,
// exp(-tau_l); with the texel's light they all take 1, whatever the light's angle.
// So the ray's first ST_SURFACE_SAMPLES dense samples (optical depth above 1 across a
// transport texel) take, after the ray loop, the light ST_SURFACE_TEXELS texels toward the
// light times their own attenuation toward it, averaged over the matter they show
// (st_surfaceChange),
//   L_local = L_ahead f;
// and only the single scattering's share of the light takes it, per colour channel (the
// rest, multiply scattered, does not come from the light's direction):
//   L' = (1 - beta) L + beta L_local,   beta = A_1 / A  (times the brightest light's share),
//   A_1 = omega/2 (1 - ln 2)               single scattering's plane albedo, mu_0 = 1
//   A   = (1 - g) / (1 + 2 g), g = sqrt(1 - omega)   all orders (Hapke 1981's H function)
// Two texels, not one: the read's trilinear stencil then lies past the surface's own
// texel, which an oblique light's sweep darkens; one texel away, a face lit at 60 degrees
// read 0.73 of the light a face lit straight on read, two texels away 0.97
// (TransportVolume.DenseFaceDarkensWithTheLightsAngle's slab).
// omega the sample's colour: beta = 0.15 for white bone, 0.33 at 0.9, 1 as omega -> 0.
// After the loop, not in it: the composite is linear in the light, so a sample's change is
// its weight times its colour's change; and llvmpipe runs the body of an if in the loop
// for every sample (masked): the same reads in the loop made still frames 2.3x slower. The
// loop keeps two numbers a sample (where on the ray, what of the ray is left there); the
// rest is read again after it. Two samples of two points each: the first two samples carry
// most of a dense face's weight (bone at the CT head's 0.5 mm steps: 0.55 and 0.25); a
// third came closer to the reference on the CT head by 2 % (RMSE 0.01237 against 0.01262),
// but two already take the still frame to about the 1.2x stock composite it may cost on
// llvmpipe (docs/rendering.md).
const int ST_SURFACE_SAMPLES = 2;
const int ST_SURFACE_POINTS = 2;
const float ST_SURFACE_TEXELS = 2.0; // the march's length, in transport texels
const int ST_EDGE_HALVINGS = 4;
vec4 st_surfaceAt;     // the samples' places: ray steps from st_rayStart
vec4 st_surfaceLeft;   // what of the ray was left at each: 1 - its alpha before the sample
int st_surfaceCount;
// Of the surface whose matter the kept samples show (st_surfaceChange):
vec3 st_surfaceEntry;  // where its matter begins
float st_surfaceFirst; // the length of it the first sample shows, in ray steps
float st_surfaceDepth; // the ray's optical depth in it before the second sample (tau_s)
float st_surfaceTau;   // the light's optical depth where it begins (a)
float st_surfaceRise;  // the light's optical depth's rise per unit of the ray's (c)
vec3 st_surfaceAhead;  // the texels' light ST_SURFACE_TEXELS texels toward the light
vec3 st_rayStart;      // the ray's first position (g_dataPos)
float st_perStep;      // 1 / |g_dirStep|^2: a position's steps from the start
float st_surfaceAlpha; // a sample's opacity above which its optical depth across a texel is 1
mat4 st_rayToWorld;    // ray position (g_dataPos) -> world
mat3 st_worldToData;   // world -> ray position, directions only

// The step toward the brightest light from ray position p: one transport texel long (xyz,
// ray coordinates) and its world length (w).
vec4 st_surfaceStep(vec3 p)
{
  vec3 toLight = st_lightDir[st_surfaceLight];
//ST::IF POSITIONAL
  if (st_lightPositional[st_surfaceLight] != 0)
  {
    vec4 world = st_rayToWorld * vec4(p, 1.0);
    toLight = normalize(st_lightPos[st_surfaceLight] - world.xyz / world.w);
  }
//ST::ENDIF
  vec3 step = st_worldToData * toLight;
  vec3 texels = mat3(st_toTransport) * step * vec3(textureSize(st_transport, 0));
  step /= max(length(texels), 1.0e-12);
  return vec4(step, length(mat3(st_rayToWorld) * step));
}

// The scalar the ray's transfer functions take at ray position p, as the composite step
// reads it.
vec4 st_scalarAt(vec3 p)
{
//ST::IF DEPENDENT
  return texture3D(in_volume[0], p) * in_volume_scale[0] + in_volume_bias[0];
//ST::ELSE
  return vec4(texture3D(in_volume[0], p).r * in_volume_scale[0].r + in_volume_bias[0].r);
//ST::ENDIF
}

// The opacity (one ray step's) of the volume at ray position p; none outside it.
float st_opacityAt(vec3 p)
{
  if (any(lessThan(p, in_texMin[0])) || any(greaterThan(p, in_texMax[0])))
  {
    return 0.0;
  }
  return computeOpacity(st_scalarAt(p));
}

// The optical depth toward the light over `step` from ray position p: ST_SURFACE_POINTS
// points, each -ln(1 - alpha) (length / d_s), alpha being one ray step's opacity, times
// OcclusionStrength (st_occlusionScale: world units here), as the transport volume's.
float st_depthToward(vec3 p, vec4 step)
{
  float kept = 1.0;
  for (int i = 0; i < ST_SURFACE_POINTS; ++i)
  {
    kept *= 1.0 - st_opacityAt(p + ((float(i) + 0.5) / float(ST_SURFACE_POINTS)) * step.xyz);
  }
  return -log(max(kept, 1.0e-30)) * st_occlusionScale * step.w /
    (float(ST_SURFACE_POINTS) * in_sampleDistance);
}

// Where the opacity crosses `edge` between ray positions `outside` (below it, opacity
// outsideAlpha) and `inside` (above it): ST_EDGE_HALVINGS halvings and a linear
// interpolation of the opacity in the last interval (continuous, where the last halving's
// midpoint jumped from pixel to pixel). An `outside` above the edge too gives `outside`.
vec3 st_edgeBetween(vec3 outside, float outsideAlpha, vec3 inside, float insideAlpha, float edge)
{
  for (int i = 0; i < ST_EDGE_HALVINGS; ++i)
  {
    vec3 middle = 0.5 * (outside + inside);
    float middleAlpha = st_opacityAt(middle);
    bool dense = middleAlpha >= edge;
    inside = dense ? middle : inside;
    insideAlpha = dense ? middleAlpha : insideAlpha;
    outside = dense ? outside : middle;
    outsideAlpha = dense ? outsideAlpha : middleAlpha;
  }
  float t = clamp((edge - outsideAlpha) / max(insideAlpha - outsideAlpha, 1.0e-6), 0.0, 1.0);
  return mix(outside, inside, t);
}

// The light the ray loop gave the sample at ray step i, position p (its st_F, shown). With
// grouped reads, the geometric interpolation between its group's two reads, as
// scatterer_shading_impl.glsl takes it; read at p instead, a sample in a group that
// crossed a surface was taken away with other light than the loop gave it, and a smooth
// surface showed dots where the groups' phase met the surface's (surface_probe.py).
vec3 st_loopLight(float i, vec3 p)
{
//ST::IF GROUPED
  const float n = float(@LIGHT_STRIDE@);
  float index = floor(i + 0.5);
  float k = mod(index, n);
  vec3 start = max(
    st_shownLight(st_transportRead(st_rayStart + (index - k) * g_dirStep)), st_lightFloor);
  vec3 end = max(
    st_shownLight(st_transportRead(st_rayStart + (index - k + n) * g_dirStep)), st_lightFloor);
  return start * pow(st_strideRoot(end / start), vec3(k));
//ST::ELSE
  return st_shownLight(st_transportRead(p));
//ST::ENDIF
}

// What sample k changes in the composite: its weight times its colour lit by L' less its
// colour lit by the light the loop gave it (st_loopLight).
vec3 st_surfaceChange(int k)
{
  vec3 p = st_rayStart + st_surfaceAt[k] * g_dirStep;
  vec4 scalar = st_scalarAt(p);
  float alpha = computeOpacity(scalar);
  vec3 colour = computeColor(scalar, alpha).rgb;
  vec3 lit = st_loopLight(st_surfaceAt[k], p);
  // A sample's opacity is that of a ray step, optical depth tau_s. The composite gives a
  // surface's first sample that whole opacity whatever part of its step the matter fills:
  // it shows the first tau_s of the ray's optical depth s beyond where the matter begins
  // (the edge where the opacity reaches half the sample's), weighted as the step
  // composites it, exp(-s); the sample after it, the next tau_s. Its single scattering's
  // light is that weight's mean of the light's attenuation, exp(-(a + c s)): a the light's
  // optical depth where the matter begins (ST_SURFACE_POINTS points on the way to
  // L_ahead), c its rise per unit of s (mu_v / mu_l in a uniform half-space):
  //   f = exp(-a - c s_0) (1 - exp(-(1 + c) tau_s)) / ((1 + c)(1 - exp(-tau_s))),
  // s_0 = 0 for the first sample, its tau_s for the next. Both depths hold whatever the
  // ray's phase: taken within the sample's own step, the light followed that phase, in
  // rings across a smooth surface (surface_probe.py's torus, docs/hard-cases.md). Taken at
  // the weight's centre, exp(-tau_l(s_c)) (e^-x is convex), a face lit at 60 degrees
  // showed less of its light lit straight on than its texels' light alone. The multiply
  // scattered share takes the texels' light at the weight's centre,
  //   u_c = 1 / tau_s - exp(-tau_s) / (1 - exp(-tau_s))   of the slab (1/2 for a thin one).
  bool follows = k > 0; // the exit calls it for a second sample that follows the first
  float tauS = max(-log(max(1.0 - alpha, 1.0e-30)), 1.0e-4);
  float centre = tauS < 1.0e-3 ? 0.5 - tauS / 12.0 : 1.0 / tauS - exp(-tauS) / (1.0 - exp(-tauS));
  float depth = follows ? st_surfaceDepth : 0.0;
  if (!follows)
  {
    // Where the matter begins: where the opacity reaches half the sample's, between the
    // step's two ends.
    vec3 before = p - g_dirStep;
    st_surfaceEntry = st_edgeBetween(before, st_opacityAt(before), p, alpha, 0.5 * alpha);
    // Matter denser beyond the sample (it lay in an edge's rise) takes the sample's opacity
    // within a shorter length, tau_s / tau steps, tau that matter's optical depth a step:
    // taken a step long, a sample in a sharp edge took the light from inside the opaque
    // matter behind it, a dark dot.
    float tau = -log(max(1.0 - st_opacityAt(st_surfaceEntry + centre * g_dirStep), 1.0e-30));
    st_surfaceFirst = min(1.0, tauS / max(tau, 1.0e-30));
    vec3 weightCentre = st_surfaceEntry + st_surfaceFirst * centre * g_dirStep;
    vec4 toLight = st_surfaceStep(weightCentre);
    vec4 march = ST_SURFACE_TEXELS * toLight;
    st_surfaceAhead = st_transportRead(weightCentre + march.xyz);
    st_surfaceTau = st_depthToward(st_surfaceEntry, march);
    // c: from a mean free path in along the ray (half a step to a step), the length toward
    // the light to where the matter ends (the same edge, within a texel), over the length
    // in: in a uniform half-space mu_v / mu_l. From the march's points instead, a voxel
    // apart, c came out about 0.4 for a face lit straight on (1), half a voxel apart 0.72;
    // from less than half a step in, the halvings' error over the tiny length darkened
    // opaque faces.
    float depthIn = clamp(st_surfaceFirst / tauS, 0.5, 1.0); // ray steps
    vec3 deeper = st_surfaceEntry + depthIn * g_dirStep;
    vec3 beyond = deeper + toLight.xyz;
    vec3 matterEnd = st_edgeBetween(beyond, st_opacityAt(beyond), deeper, alpha, 0.5 * alpha);
    st_surfaceRise = st_occlusionScale * (length(matterEnd - deeper) / length(toLight.xyz)) *
      toLight.w / (depthIn * in_sampleDistance);
    st_surfaceDepth = tauS;
  }
  vec3 q = st_surfaceEntry +
    (follows ? st_surfaceFirst + centre : st_surfaceFirst * centre) * g_dirStep;
  vec3 received = st_transportRead(q);
  float c = st_surfaceRise;
  float attenuation = exp(-st_surfaceTau - c * depth) * (1.0 - exp(-(1.0 + c) * tauS)) /
    ((1.0 + c) * max(1.0 - exp(-tauS), 1.0e-30));
  vec3 local = attenuation * st_surfaceAhead;
  vec3 omega = clamp(colour, 0.0, 1.0);
  vec3 g = sqrt(1.0 - omega);
  vec3 beta = clamp(0.1534 * omega * (1.0 + 2.0 * g) / max(1.0 - g, 1.0e-4), 0.0, 1.0);
  // Mixed before the display's compression, which is monotone: less light arriving never
  // shows brighter (compressed first, the mix of a shadowed texel's light showed brighter
  // than the unshadowed one's: HardCases.OpacityOne).
  vec3 shown = st_shownLight(mix(received, local, beta * st_surfaceShare));
  return st_surfaceLeft[k] * alpha *
    (clamp(colour * shown, 0.0, 1.0) - clamp(colour * lit, 0.0, 1.0));
}
//ST::ENDIF
//ST::ENDIF

//ST::IF PERSAMPLE
// Material of a normalized scalar (the TF-table coordinate), -1 for none (st_probe's
// -1e6: outside the volume). Clamped as VTK's tables clamp it: the ray caster's scalar
// at the data's maximum came out a little above 1 for 8-bit data (by 0.002 to 0.01),
// beyond the last material's range, and a ball at the data's maximum was left unlit.
int st_material(float s)
{
  if (s < -1.0e5)
  {
    return -1;
  }
  s = clamp(s, 0.0, 1.0);
  for (int m = 0; m < ST_MAX_MATERIALS; ++m)
  {
    if (m >= st_materialCount) break;
    if (s >= st_matRange[m].x && s <= st_matRange[m].y)
    {
      return m;
    }
  }
  return -1;
}

// Which template of its material a sample uses: hashed from the voxel, so the
// noise of individual templates becomes a fine, stable grain.
int st_templateIndex(vec3 texPos, int salt)
{
  // Voxel index in the whole volume (st_indexOrigin: the image's first extent
  // index), so pieces of a split volume pick templates as the whole volume does.
  uvec3 v = uvec3(ivec3(texPos * vec3(textureSize(in_volume[0], 0)) + st_indexOrigin)) + uvec3(salt);
  uint h = v.x * 73856093u ^ v.y * 19349663u ^ v.z * 83492791u;
  h ^= h >> 13u;
  h *= 0x5bd1e995u;
  h ^= h >> 15u;
  return int(h % uint(st_templatesPerMaterial));
}

//ST::IF FETCH
// Normalized scalar and per-sample-distance opacity at a texture position, from
// the nearest voxel (texelFetch: one texel, where the ray itself filters 8);
// outside the volume there is nothing (no material, no opacity).
vec2 st_probe(vec3 texPos)
{
  if (any(lessThan(texPos, vec3(0.0))) || any(greaterThanEqual(texPos, vec3(1.0))))
  {
    return vec2(-1.0e6, 0.0);
  }
  ivec3 size = textureSize(in_volume[0], 0);
  float s = texelFetch(in_volume[0], ivec3(texPos * vec3(size)), 0).r * in_volume_scale[0].r +
    in_volume_bias[0].r;
  return vec2(s, computeOpacity(vec4(s)));
}
//ST::ENDIF

//ST::IF SHADOW
// Transmittance over `dist` template radii of matter with the per-sample
// opacity `alpha`: (1 - alpha)^(strength * radius * dist / sampleDistance).
// Always in [0, 1]; alpha >= 1 blocks completely, NaN counts as empty.
float st_transmittance(float alpha, float dist)
{
  if (!(alpha > 0.0))
  {
    return 1.0; // nothing there, or NaN from a NaN voxel: no occluder
  }
  if (!(alpha < 1.0))
  {
    return 0.0;
  }
  float e = max(st_occlusionScale * dist / in_sampleDistance, 1.0e-4);
  return pow(clamp(1.0 - alpha, 0.0, 1.0), e);
}
//ST::ENDIF

// Photon loop over one template row. Per light: den = intensity of the photons
// toward it, lit = the part that arrives in the sample's own material (or in
// empty space), tinted = the part that arrives through another material,
// coloured by it.
void st_gatherTemplate(int row, vec3 texPos, int m, float transmittance, vec3 toLight[ST_LIGHT_SLOTS],
  inout float lit[ST_LIGHT_SLOTS], inout vec3 tinted[ST_LIGHT_SLOTS], inout float den[ST_LIGHT_SLOTS])
{
  for (int j = 0; j < st_photonCount; ++j)
  {
    vec4 photon = texelFetch(st_templates, ivec2(j, row), 0);
    // Photons are sorted by intensity: once ray transmittance x photon
    // intensity is below the threshold, no later photon can show either.
    if (photon.w <= 0.0 || transmittance * photon.w < st_photonThreshold)
    {
      break;
    }
    bool towardAny = false;
    for (int l = 0; l < ST_LIGHT_SLOTS; ++l)
    {
      if (l >= st_lightCount) break;
      towardAny = towardAny || dot(photon.xyz, toLight[l]) > 0.0;
    }
    if (!towardAny)
    {
      continue;
    }
    float weight = photon.w;
//ST::IF BLEED
    bool foreign = false;
    vec3 tint = vec3(1.0);
//ST::ENDIF
//ST::IF FETCH
    vec3 offset = photon.x * st_toTexX + photon.y * st_toTexY + photon.z * st_toTexZ;
    float dist = length(photon.xyz);
    vec2 probe = st_probe(texPos + offset);
    int mp = st_material(probe.x);
//ST::IF BOUNDARY
    if (mp >= 0 && mp != m)
    {
      // Section 3.4: in another material light travels at n_m / n_mp of the
      // speed, so the photon sits that much nearer or farther; its intensity
      // scales with the opacity ratio (at most 1).
      float speed = st_speedRatio[m * ST_MAX_MATERIALS + mp];
      offset *= speed;
      dist *= speed;
      weight *= st_opacityRatio[m * ST_MAX_MATERIALS + mp];
      probe = st_probe(texPos + offset);
      mp = st_material(probe.x);
    }
//ST::ENDIF
//ST::IF SHADOW
    weight *= st_transmittance(probe.y, dist);
//ST::ENDIF
//ST::IF BLEED
    if (mp >= 0 && mp != m)
    {
      foreign = true;
      tint = st_matColor[mp];
    }
//ST::ENDIF
//ST::ENDIF
    for (int l = 0; l < ST_LIGHT_SLOTS; ++l)
    {
      if (l >= st_lightCount) break;
      if (dot(photon.xyz, toLight[l]) > 0.0)
      {
        den[l] += photon.w;
        float w = weight;
//ST::IF THIN
        if (w > 0.0)
        {
          // Fig. 4: a thin part (an ear) sees no blocker inside the template;
          // look on from the photon toward the light for the head behind it.
          vec3 towardLight = toLight[l].x * st_toTexX + toLight[l].y * st_toTexY +
            toLight[l].z * st_toTexZ;
          w *= st_transmittance(
            st_probe(texPos + offset + towardLight * ((st_longRange - 1.0) * dist)).y, dist);
        }
//ST::ENDIF
//ST::IF BLEED
        if (foreign)
        {
          tinted[l] += w * tint;
          continue;
        }
//ST::ENDIF
        lit[l] += w;
      }
    }
  }
}

// Illumination of a sample of material m at texPos, as a factor on its own
// colour (st_F) and a colour added by bleeding (st_B): colour = c * F + B.
// Unoccluded, F = ambient + sum of light colours and B = 0; occlusion only
// lowers F and B. transmittance is what is left of the ray at this sample.
void st_illuminate(vec3 texPos, int m, float transmittance, out vec3 F, out vec3 B)
{
  vec3 toLight[ST_LIGHT_SLOTS];
//ST::IF POSITIONAL
  vec4 world = in_volumeMatrix[0] * in_textureDatasetMatrix[0] * vec4(texPos, 1.0);
  world /= world.w;
//ST::ENDIF
  float lit[ST_LIGHT_SLOTS];
  float den[ST_LIGHT_SLOTS];
  vec3 tinted[ST_LIGHT_SLOTS];
  for (int l = 0; l < ST_LIGHT_SLOTS; ++l)
  {
    if (l >= st_lightCount) break;
    toLight[l] = st_lightDir[l];
//ST::IF POSITIONAL
    if (st_lightPositional[l] != 0)
    {
      toLight[l] = normalize(st_lightPos[l] - world.xyz);
    }
//ST::ENDIF
    lit[l] = 0.0;
    den[l] = 0.0;
    tinted[l] = vec3(0.0);
  }
  int firstRow = m * st_templatesPerMaterial;
  st_gatherTemplate(firstRow + st_templateIndex(texPos, 0), texPos, m, transmittance, toLight,
    lit, tinted, den);
//ST::IF BLEND2
  st_gatherTemplate(firstRow + st_templateIndex(texPos, 7919), texPos, m, transmittance, toLight,
    lit, tinted, den);
//ST::ENDIF
  F = st_ambient;
  B = vec3(0.0);
  for (int l = 0; l < ST_LIGHT_SLOTS; ++l)
  {
    if (l >= st_lightCount) break;
    // No photon toward this light bright enough to matter: unoccluded.
    float inv = den[l] > 0.0 ? 1.0 / den[l] : 0.0;
    F += st_lightColor[l] * (den[l] > 0.0 ? lit[l] * inv : 1.0);
//ST::IF BLEED
    B += st_lightColor[l] * tinted[l] * inv;
//ST::ENDIF
  }
}
//ST::ENDIF
