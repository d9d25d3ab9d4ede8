// SPDX-License-Identifier: MIT
// Entry point of the formflow binary.
#include "formflow/app/cli.hpp"
#include "formflow/app/stop_signals.hpp"

int main(int argc, char** argv) {
  formflow::app::install_stop_handlers();
  return formflow::app::run_cli(argc, argv);
}
