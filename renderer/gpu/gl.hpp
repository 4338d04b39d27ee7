#pragma once
// The one include for OpenGL in Transparency Lab: the glad loader generated at configure time.
// Nothing includes GL/gl.h directly; entry points come from the active GpuContext's loader.
#include <glad/gl.h>
