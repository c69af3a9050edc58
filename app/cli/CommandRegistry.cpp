#include "cli/CommandRegistry.h"

namespace fm::cli {

std::vector<Command>& commandRegistry() {
    static std::vector<Command> registry;  // function-local: safe across static init order
    return registry;
}

}  // namespace fm::cli
