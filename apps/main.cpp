// The `vssw` program: every command is implemented in the vssw_cli library (cli.hpp).
#include <iostream>

#include "apps/cli.hpp"

int main(int argc, char** argv) { return vssw::cli::run(argc, argv, std::cout, std::cerr); }
