#pragma once
// The only way app code reaches OpenGL: glad's GL 3.3 core loader, generated at build time.
// Every gl* call goes through a pointer loaded from the active context (GLFW or OSMesa), so the
// same drawing code runs in a window and headless. Never include <GL/gl.h> next to this.
#include <glad/gl.h>
