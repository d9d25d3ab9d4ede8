// SPDX-License-Identifier: MIT
// Entry point of the formflow binary.
#include "formflow/app/cli.hpp"

int main(int argc, char** argv) {
  return formflow::app::run_cli(argc, argv);
}
