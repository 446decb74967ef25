// delaunay2d, as installed: the program of cli/delaunay2d.cpp with no test hooks.
#include "delaunay2d.h"

int main(int argc, char** argv) { return dt::cli::run(argc, argv, {}); }
