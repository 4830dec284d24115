//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 1: transmittance sweep (one slice per draw).
//
// Light propagation slice by slice along the light's dominant grid axis
// (Behrens & Ratering 1998; Ropinski et al. 2010): a texel of slice k takes the
// transmittance of slice k -/+ 1 where the line toward the light crosses it, and
// multiplies it by Beer-Lambert over the step between the two:
//   T(p) = T(q) * exp(-integral_q^p sigma_t ds)          (Beer-Lambert)
// so T holds the fraction of the light's energy that reaches p through the whole
// volume, in O(N) per light. Directional lights: one direction for all texels.
// Positional lights: the direction toward the light per texel, and slices are
// swept away from the light's own slice on both sides (the radial variant).
//
// A piece of a distributed volume (vtkScattererLightExchange): the light that enters
// what the piece holds (its voxels and ghost layers) has already crossed the pieces
// in front of it, whose optical depth beyond the ghost layers, tau_front, the
// light-space map st_enteringDepth holds (scatterer/LightSpace.h). By Beer-Lambert
// over the parts of the path,
//   T(p) = T_piece(p) * exp(-tau_front(line through p))
// The slices carry T_piece; the transmittance texture gets T.
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler2D st_previous;     // the slice swept before this one
uniform int st_hasPrevious;        // 0: first slice of a sweep, T = 1
uniform float st_slice;            // this slice's index along the sweep axis
uniform vec3 st_sweepDims;         // (rows, columns, slices) of the sweep texture
uniform mat3 st_worldToGrid;       // world vector -> grid-index vector
uniform mat3 st_gridToWorld;       // grid-index vector -> world vector
uniform vec3 st_lightToward;       // directional: unit vector toward the light (world)
uniform vec3 st_lightPosition;     // positional: world position
uniform int st_lightPositional;
uniform int st_substeps;           // extinction samples per step (volume voxels per texel)
uniform mat4 st_texToIndex;        // volume texture coordinates -> structured index
uniform int st_entering;           // 0: none; 1: directional map; 2: positional (octahedral)
uniform sampler2D st_enteringDepth;
uniform vec3 st_enteringLight;     // positional: the light (index space)
uniform vec3 st_enteringU;         // directional: the map plane's basis (index space)
uniform vec3 st_enteringV;
uniform vec2 st_enteringLo;        // directional: the map's corner on the plane
uniform float st_enteringSide;     // directional: the map's side (index units)

// Mirrors scatterer::lightspace::Map::coordinate.
vec2 st_octahedral(vec3 d)
{
  vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
  if (d.z < 0.0)
  {
    vec2 s = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    p = (vec2(1.0) - abs(p.yx)) * s;
  }
  return p;
}

// The optical depth in front of this piece on the light's line through index i.
float st_depthInFront(vec3 i)
{
  if (st_entering == 0)
  {
    return 0.0;
  }
  vec2 c;
  if (st_entering == 2)
  {
    vec3 d = i - st_enteringLight;
    c = st_octahedral(length(d) > 0.0 ? normalize(d) : vec3(0.0, 0.0, 1.0)) * 0.5 + vec2(0.5);
  }
  else
  {
    c = (vec2(dot(i, st_enteringU), dot(i, st_enteringV)) - st_enteringLo) / st_enteringSide;
  }
  return texture(st_enteringDepth, c).r;
}

void main()
{
  vec3 js = vec3(floor(texCoord * st_sweepDims.xy), st_slice);
  vec3 j = transpose(st_toSweep) * js;
  float T = 1.0;
  if (st_hasPrevious != 0)
  {
    vec3 toward = st_lightToward;
    if (st_lightPositional != 0)
    {
      vec4 p = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
      toward = st_lightPosition - p.xyz / p.w;
    }
    vec3 ds = st_toSweep * (st_worldToGrid * toward);
    // One slice toward the light; a light nearly in this slice's plane would
    // shift sideways without bound: at most 4 texels per step.
    float along = max(abs(ds.z), length(ds.xy) / 4.0);
    vec3 stepSweep = ds / max(along, 1.0e-20);
    stepSweep.z = sign(ds.z);
    vec3 qs = js + stepSweep;
    vec3 stepGrid = transpose(st_toSweep) * stepSweep;
    float len = length(st_gridToWorld * stepGrid);
    float tau = 0.0;
    for (int i = 0; i < st_substeps; ++i)
    {
      vec3 g = j + stepGrid * ((float(i) + 0.5) / float(st_substeps));
      tau += st_attenuationAt(st_gridToTexture(g));
    }
    tau *= len / float(st_substeps);
    // Outside the grid the light has crossed no matter: the border reads 1.
    float Tq = texture(st_previous, (qs.xy + vec2(0.5)) / st_sweepDims.xy).r;
    T = Tq * exp(-tau);
  }
  gl_FragData[0] = vec4(T);
  vec3 index = (st_texToIndex * vec4(st_gridToTexture(j), 1.0)).xyz;
  gl_FragData[1] = vec4(T * exp(-st_depthInFront(index)));
}
