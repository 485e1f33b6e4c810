// The C interface's definitions (include/conescan/c_interface.hpp), in the one C++ file of
// a program that defines them.
#include "conescan/c_interface.hpp"
