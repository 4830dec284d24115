//VTK::System::Dec
//============================================================================
// Light transport volume: the vertex shader of the passes that draw whole 3D
// textures (every pass but the sweep). The full-screen quad is drawn once per
// layer as instances of one draw call; the instance says which layer
// (scatterer_transport_layers_gs.glsl routes it there).
//============================================================================
in vec4 ndCoordIn;
in vec2 texCoordIn;
out vec2 st_quadCoord;
flat out int st_instance;

void main()
{
  gl_Position = ndCoordIn;
  st_quadCoord = texCoordIn;
  st_instance = gl_InstanceID;
}
