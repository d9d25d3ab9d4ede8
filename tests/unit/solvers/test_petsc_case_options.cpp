// SPDX-License-Identifier: MIT
// The PETSc options a case file may carry: solver choices and their parameters pass,
// viewers, monitors, options files, paths and the rest of PETSc's database are refused
// by name.
#include "formflow/solvers/petsc_case_options.hpp"

#include <gtest/gtest.h>

#include <string>

namespace formflow::solvers {
namespace {

/// The refusal of `text`, or "" when every option passes.
std::string refusal_of(const std::string& text) {
  return case_petsc_options_refusal(text).value_or("");
}

TEST(PetscCaseOptions, TheSolverOptionsTheDocsShowPass) {
  for (const char* text : {
           "-ksp_type cg -pc_type gamg -ksp_rtol 1e-10",
           "-ksp_type fgmres -ksp_rtol 1e-12 -pc_type fieldsplit -pc_fieldsplit_type schur "
           "-pc_fieldsplit_schur_fact_type full -pc_fieldsplit_schur_precondition selfp "
           "-fieldsplit_u_ksp_type preonly -fieldsplit_u_pc_type hypre "
           "-fieldsplit_p_ksp_type preonly -fieldsplit_p_pc_type lu",
           "-fieldsplit_u_pc_hypre_boomeramg_strong_threshold 0.5 "
           "-fieldsplit_u_pc_hypre_boomeramg_coarsen_type HMIS "
           "-fieldsplit_u_pc_hypre_boomeramg_interp_type ext+i "
           "-fieldsplit_u_pc_hypre_boomeramg_P_max 4 "
           "-fieldsplit_u_pc_hypre_boomeramg_relax_type_down l1-Gauss-Seidel "
           "-pc_hypre_boomeramg_relax_type_all symmetric-SOR/Jacobi",
           "-fieldsplit_u_pc_gamg_threshold 0.02 -fieldsplit_u_pc_gamg_agg_nsmooths 0 "
           "-mg_levels_ksp_type chebyshev -mg_levels_pc_type sor -mg_levels_1_ksp_max_it 3 "
           "-mg_coarse_pc_type lu -ksp_chebyshev_esteig 0,0.1,0,1.1",
           "-mat_mumps_icntl_7 4 -mat_mumps_icntl_14 50 -mat_mumps_cntl_1 0.01 "
           "-pc_factor_mat_solver_type mumps -mat_type is -pc_type bddc",
           "-sub_pc_type ilu -sub_pc_factor_levels 1 -pc_type bjacobi -ksp_max_it 1000 "
           "-ksp_gmres_restart 100 -ksp_initial_guess_nonzero",
           "-ksp_rtol 1e-12 -formflow_inexact_steps 0 -formflow_velocity_node_blocks 0 "
           "-mat_partitioning_type average",
       })
    EXPECT_EQ(refusal_of(text), "") << text;
}

TEST(PetscCaseOptions, ViewersMonitorsAndLogsAreRefusedByName) {
  for (const char* name :
       {"-ksp_view", "-mat_view", "-ksp_monitor", "-log_view", "-malloc_dump", "-pc_mg_log",
        "-fieldsplit_u_ksp_view", "-mg_levels_ksp_monitor_true_residual", "-ksp_view_mat",
        "-pc_hypre_boomeramg_print_statistics", "-snes_monitor", "-ksp_monitor_lg_residualnorm",
        "-mat_mumps_icntl_view", "-pc_bddc_dump"}) {
    const std::string refusal = refusal_of(std::string(name) + " ascii:/tmp/formflow-leak");
    EXPECT_NE(refusal.find(name), std::string::npos) << name << ": " << refusal;
  }
}

TEST(PetscCaseOptions, OptionsFilesHelpAndTheRestOfTheDatabaseAreRefused) {
  for (const char* text :
       {"-options_file /etc/passwd", "-help", "-prefix_push fieldsplit_u_", "-prefix_pop",
        "-options_left", "-info", "-on_error_attach_debugger", "-vec_type standard",
        "-fieldsplit_type schur", "-fieldsplit__ksp_type cg", "-ksp_converged_reason",
        "-mat_mumps_icntl_1 6", "-mat_mumps_icntl_22 1", "-mat_mumps_icntl_x 1",
        "-ksp_type_extra cg", "-petscspace_degree 2", "-options_monitor"}) {
    const std::string refusal = refusal_of(text);
    const std::string name = std::string(text).substr(0, std::string(text).find(' '));
    EXPECT_NE(refusal.find(name), std::string::npos) << text << ": " << refusal;
  }
}

TEST(PetscCaseOptions, ValuesThatLookLikePathsOrViewersAreRefused) {
  for (const char* text :
       {"-ksp_type ascii:/tmp/out", "-pc_type /etc/passwd", "-ksp_rtol ../x", "-pc_type a\\b",
        "-pc_hypre_boomeramg_relax_type_all /SOR/Jacobi", "-pc_type python",
        "-fieldsplit_u_ksp_type python", "-mat_type binary:matrix.dat", "-ksp_type ~/x"}) {
    const std::string refusal = refusal_of(text);
    EXPECT_NE(refusal, "") << text;
    EXPECT_NE(refusal.find(std::string(text).substr(0, std::string(text).find(' '))),
              std::string::npos)
        << refusal;
  }
}

TEST(PetscCaseOptions, TheFirstRefusedOptionIsNamed) {
  const std::string refusal = refusal_of("-ksp_type cg -pc_type gamg -ksp_view -log_view");
  EXPECT_NE(refusal.find("-ksp_view"), std::string::npos) << refusal;
  EXPECT_EQ(refusal.find("-log_view"), std::string::npos) << refusal;
}

TEST(PetscCaseOptions, TheHintSaysWhatIsAllowedAndWhereTheRestGoes) {
  const std::string_view allowed = case_petsc_options_allowed();
  for (const char* word : {"-ksp_type", "-pc_hypre_*", "-mat_mumps_icntl_*", "command line"})
    EXPECT_NE(allowed.find(word), std::string_view::npos) << word;
}

} // namespace
} // namespace formflow::solvers
