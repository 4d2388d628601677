// The blockfrag executable: the command line lives in mpi_driver/cli.
#include "mpi_driver/cli/app.hpp"

int main(int argc, char** argv) { return blockfrag::run_command_line(argc, argv); }
