// GL debug output, on in every run: errors and warnings from the driver arrive at once
// (synchronous) with a message, and are counted so a headless run can fail on any GL error.
#pragma once

#include <string>

namespace ocean {

struct GlDebugStats {
    int errors = 0;
    std::string first_error;
};

// Installs the callback on the current context and starts counting afresh. Set OCEAN_GL_DEBUG=verbose to also print
// the driver's performance and informational messages.
void enable_gl_debug_output();
const GlDebugStats& gl_debug_stats();
// Also drains glGetError(), which catches errors a driver did not report through the callback.
void check_gl_errors(const char* where);

}  // namespace ocean
