#!/usr/bin/env bash
# The main job: reproduces the paper's Figs. 2 and 3 and compares the engine with the closed forms.
#
#   bash scripts/reproduce.sh
#
# Installs what is missing, builds mdrsim (in $BUILD_DIR, default build, configured like the
# tests), runs the scenes and sweeps into results/ ($RESULTS_DIR), draws the figures (PNG and
# SVG) and prints the comparison table, then measures speed against accuracy (bench/) and
# draws that chart. Exits non-zero if a run fails, any simulated critical force is further
# than 2e-3 F0 from the paper's analytic value, the fretting loop is off its closed forms beyond
# O(1/N), a Maugis-Dugdale pull-off is more than 1e-6 off Maugis' (or a cone's status off pi/4),
# a graded parabola's pull-off is off its closed form (1e-6, or the row's estimate), a
# viscoelastic force curve is off Lee-Radok/Ting beyond the row's stated error,
# an accuracy target of the bench is missed, or the two engines disagree on a Fig. 2
# critical force; never for a speed target (see below).
# Works from any directory.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

build_dir="${BUILD_DIR:-build}"
results="${RESULTS_DIR:-results}"
mdrsim="$build_dir/apps/mdrsim"
# Debian's interpreter: it has numpy and matplotlib (a python3 earlier on PATH may not).
py=/usr/bin/python3

# Installation and build logs go to standard error: standard output is the report alone
# (the figures written and the comparison table), e.g. bash scripts/reproduce.sh > report.txt
bash scripts/setup.sh >&2
BUILD_DIR="$build_dir" bash scripts/build.sh mdrsim mdrsim_accuracy mdrsim_engines >&2
mkdir -p "$results"

# u/d0 from 0 to 4 in 41 values; d0 = 2.2614848269449475e-6 m for the Fig. 3a scenes (R = 1 cm,
# E* = 1 MPa, dgamma = 0.05 J/m^2), so 4 d0 = 9.045939307779790e-6 m.
vary="loading.tangential.displacement=0:9.045939307779790e-6:41"
threads=2

echo "== Fig. 2: JKR pull-off trajectories" >&2
for control in fixed_grips fixed_load; do
  "$mdrsim" run "scenes/fig2_$control.toml" \
    --trajectory "$results/fig2_$control.csv" --json "$results/fig2_$control.json"
done

echo "== Fig. 3a: critical forces against the tangential displacement" >&2
# Each sweep with the JSON of one run of its scene (the same --set values): the figures take
# the run's scales and moduli from it.
for control in fixed_grips fixed_load; do
  "$mdrsim" sweep "scenes/fig3a_$control.toml" --vary "$vary" \
    --csv "$results/fig3a_$control.csv" --force --threads "$threads"
  "$mdrsim" run "scenes/fig3a_$control.toml" --json "$results/fig3a_$control.json" --log-level warn
done
# Eq. 34 at G* != E*: the fixed-grips sweep at nu = 0.3.
"$mdrsim" sweep scenes/fig3a_fixed_grips.toml --vary "$vary" --set material.poisson_ratio=0.3 \
  --csv "$results/fig3a_fixed_grips_nu03.csv" --force --threads "$threads"
"$mdrsim" run scenes/fig3a_fixed_grips.toml --set material.poisson_ratio=0.3 \
  --json "$results/fig3a_fixed_grips_nu03.json" --log-level warn

# The same runs on the continuum route (docs/continuum.md): no springs, rtol 1e-10; the
# comparison table's `continuum` column.
echo "== the continuum route: Fig. 2 and the Fig. 3a sweeps, rtol 1e-10" >&2
continuum=(--set 'solver={method="continuum"}' --set 'discretization={rtol=1e-10}')
for control in fixed_grips fixed_load; do
  "$mdrsim" run "scenes/fig2_$control.toml" "${continuum[@]}" \
    --json "$results/fig2_${control}_continuum.json"
  "$mdrsim" sweep "scenes/fig3a_$control.toml" --vary "$vary" "${continuum[@]}" \
    --csv "$results/fig3a_${control}_continuum.csv" --force --threads "$threads"
done
"$mdrsim" sweep scenes/fig3a_fixed_grips.toml --vary "$vary" --set material.poisson_ratio=0.3 \
  "${continuum[@]}" --csv "$results/fig3a_fixed_grips_nu03_continuum.csv" --force \
  --threads "$threads"

echo "== figures" >&2
"$py" scripts/plot_paper_figures.py --results "$results"

# Beyond the paper's path: a reversible-JKR approach-retract cycle (loading programs), its
# force-displacement loop with the jump-in and the jump-out.
echo "== a loading program: the reversible JKR cycle" >&2
"$mdrsim" run scenes/programs/jkr_cycle_reversible.toml \
  --trajectory "$results/program_jkr_cycle.csv" --json "$results/program_jkr_cycle.json"
"$mdrsim" run scenes/programs/jkr_cycle_reversible.toml --set discretization.springs=128 \
  --set 'discretization.extrapolation="richardson"' --json "$results/program_jkr_cycle_richardson.json"
"$py" scripts/plot_program.py "$results/program_jkr_cycle.csv" \
  --json "$results/program_jkr_cycle.json"

# Beyond the paper: a wavy sphere's pull-off against its ripple amplitude, the amplitudes
# whose contact is not one disk shaded (docs/model.md "One contact disk"; about 3 s).
echo "== a wavy sphere: pull-off against the ripple amplitude" >&2
"$mdrsim" sweep scenes/wavy_sphere.toml --vary "profile.amplitude=0:1e-6:21" \
  --csv "$results/wavy_amplitude.csv" --force --threads "$threads" --log-level error
"$py" scripts/plot_wavy.py --csv "$results/wavy_amplitude.csv" --out "$results"

# Beyond the paper: a work of adhesion that varies with the radius, the crack-front codes'
# axisymmetric test case (w0 (1 + A sin(2 pi r / 0.1))) for A = 0, 0.1, 0.2, its loop drawn
# against the uniform JKR loop; A = 0 against the JKR closed forms, each row within 3/N of its
# rtol run (docs/scene.md "Adhesion that varies with radius"; about 1 s).
echo "== adhesion that varies with radius: the crack-front test case" >&2
for amplitude in 0 0.1 0.2; do
  ripple=(--set "material.work_of_adhesion.amplitude=$amplitude"
          --set "material.approach_work_of_adhesion.amplitude=$amplitude")
  "$mdrsim" run scenes/programs/crack_front_sinusoid.toml "${ripple[@]}" \
    --set discretization.springs=20000 --trajectory "$results/crack_front_$amplitude.csv" \
    --json "$results/crack_front_$amplitude.json" --log-level error
  "$mdrsim" run scenes/programs/crack_front_sinusoid.toml "${ripple[@]}" \
    --set discretization.rtol=1e-6 --json "$results/crack_front_${amplitude}_rtol.json" \
    --log-level error
done
echo
"$py" scripts/plot_crack_front.py --results "$results" --amplitudes 0 0.1 0.2

# Beyond the paper: Coulomb friction (docs/friction.md) at 1000 and 10000 springs, a fretting
# cycle against Cattaneo-Mindlin and Mindlin-Deresiewicz and the transition from adhesion to
# sliding friction (chi = mu F_z / F_x,peak below and above 1) against its closed forms; their
# tables are in the report, and a number beyond its O(1/N) bound fails the job (about 4 s).
echo "== friction: a fretting loop and the adhesion-to-friction transition" >&2
for n in 1000 10000; do
  "$mdrsim" run scenes/programs/fretting_parabola.toml --set "discretization.springs=$n" \
    --trajectory "$results/fretting_$n.csv" --json "$results/fretting_$n.json" --log-level error
  for chi in below above; do
    "$mdrsim" run "scenes/programs/adhesion_to_friction_chi_$chi.toml" \
      --set "discretization.springs=$n" --trajectory "$results/transition_${chi}_$n.csv" \
      --json "$results/transition_${chi}_$n.json" --log-level error
  done
done
"$py" scripts/plot_fretting.py --results "$results" --springs 1000 10000
echo
"$py" scripts/plot_transition.py --results "$results" --springs 1000 10000

# Beyond the paper: pull-off after shear (Oliver, Dalmas and Scheibert), the glued sphere
# sheared to u under friction and then pulled off, with and without rebinding, at 2000 and
# 8000 springs, against the paper's path on the continuum route; a pull-off beyond its O(1/N)
# bound fails the job (docs/friction.md "Pull-off after shear"; about 1 s).
echo "== friction: pull-off after shear" >&2
shear="0:2.5585780106932e-5:33"  # 0 .. 2 u_c
for n in 2000 8000; do
  "$mdrsim" sweep scenes/programs/pull_off_after_shear.toml \
    --vary "loading.stage.2.tangential.to=$shear" --vary "loading.rebinding=false,true" \
    --set "discretization.springs=$n" --csv "$results/pull_off_after_shear_$n.csv" --force \
    --threads "$threads" --log-level error
done
"$mdrsim" sweep scenes/fig3a_fixed_grips.toml --vary "loading.tangential.displacement=$shear" \
  "${continuum[@]}" --csv "$results/pull_off_after_shear_continuum.csv" --force \
  --threads "$threads" --log-level error
echo
"$py" scripts/plot_pull_off_after_shear.py --results "$results" --springs 2000 8000
# The same sphere on a relaxing bulk (E_0 = 10 E_inf, tau = 1 s): sheared to u over 0 .. 4 u_c
# at u_c / tau times 0.01, 1 and 100, held 1e-3 s or 10 tau, with and without rebinding
# (docs/friction.md "Pull-off after shear on a relaxing bulk"; about 4 s on 2 cores). The
# unsheared pull-offs, the relaxed curve after 10 tau and the shear that breaks the glue at
# each speed off their closed forms (to 1/N) fail the job.
echo "== friction: pull-off after shear on a relaxing bulk" >&2
"$mdrsim" sweep scenes/viscoelastic/pull_off_after_shear_relaxing.toml \
  --vary "loading.stage.4.tangential.to=0:5.1171560213864e-5:17" \
  --vary "loading.stage.4.speed=1.27929e-7,1.27929e-5,1.27929e-3" \
  --vary "loading.stage.5.duration=0.001,10" --vary "loading.rebinding=false,true" \
  --csv "$results/pull_off_after_shear_relaxing.csv" --force --threads "$threads" \
  --log-level error
"$py" scripts/plot_pull_off_after_shear_relaxing.py --results "$results"

# Beyond the paper: finite-range adhesion (Maugis-Dugdale, docs/maugis.md). The parabola's
# pull-off against Maugis' parameter lambda under a fixed load and fixed grips on the continuum
# route (rtol 1e-10), against Maugis' own equations written apart (scripts/maugis_reference.py);
# the cone's against sigma_0 / (E* tan theta), with the fixed-grips threshold pi/4 and the DMT and
# JKR limits, on the continuum route and on the spring row; the approach-retract loop against
# lambda. A P beyond 1e-6 of Maugis' (2e-6 on the row) or a cone status against pi/4 fails the
# job (about 15 s).
echo "== finite-range adhesion: the Maugis-Dugdale transition" >&2
lambdas="0.01,0.02,0.05,0.1,0.2,0.5,0.8,0.9,1,1.2,1.5,2,3,5,10,20,50,100"
# sigma_0 = x E* tan(10 deg) for x = 0.01, 0.03, 0.1, 0.3, 0.5, 0.7, 0.9, 1.2, 2, 5, 10, 30, 100
stresses="1763.269807,5289.809421,17632.69807,52898.09421,88163.49035,123428.8865,158694.2826"
stresses+=",211592.3769,352653.9614,881634.9035,1763269.807,5289809.421,17632698.07"
"$mdrsim" run scenes/maugis/maugis_parabola.toml --json "$results/maugis_parabola.json" \
  --log-level warn
"$mdrsim" run scenes/maugis/maugis_cone.toml --json "$results/maugis_cone.json" --log-level warn
# Each on both routes: the continuum's (the scenes' rtol 1e-10) and the spring row's (rtol 1e-6).
row=(--set 'solver={method="event"}' --set 'discretization={rtol=1e-6}')
for control in fixed-load fixed-grips; do
  held=(--set "loading.normal={control=\"$control\"}")
  for route in "" _row; do
    on_route=()
    if [ -n "$route" ]; then on_route=("${row[@]}"); fi
    "$mdrsim" sweep scenes/maugis/maugis_parabola.toml --vary "material.maugis_parameter=$lambdas" \
      "${held[@]}" "${on_route[@]}" --csv "$results/maugis_parabola${route}_${control/-/_}.csv" \
      --force --threads "$threads" --log-level error
    "$mdrsim" sweep scenes/maugis/maugis_cone.toml --vary "material.adhesive_stress=$stresses" \
      "${held[@]}" "${on_route[@]}" --csv "$results/maugis_cone${route}_${control/-/_}.csv" \
      --force --threads "$threads" --log-level error
  done
done
# The approach-retract cycle's loop against lambda: retracted to D = -(3/(pi lambda) + 3) in
# Maugis' depths (0.652 nm here), past every jump out.
cycle_lambdas="0.1,0.2,0.3,0.5,0.7,0.9,1,1.5,2,3,5,10,20"
cycle_ends="-8.18622e-09,-5.0716e-09,-4.03339e-09,-3.20282e-09,-2.84687e-09,-2.64911e-09"
cycle_ends+=",-2.5799e-09,-2.37226e-09,-2.26844e-09,-2.16462e-09,-2.08156e-09,-2.01927e-09"
cycle_ends+=",-1.98812e-09"
"$mdrsim" sweep scenes/maugis/maugis_cycle.toml --vary "material.maugis_parameter=$cycle_lambdas" \
  --link "loading.stage.2.normal.to=$cycle_ends" --csv "$results/maugis_cycle.csv" --force \
  --threads "$threads" --log-level error
echo
"$py" scripts/plot_maugis.py --results "$results"

# Beyond the paper: graded media (docs/graded.md). The parabola's pull-off against the grading
# exponent k in [0, 0.9] under a fixed load and fixed grips, on the continuum route (rtol 1e-10)
# and on the graded spring row (rtol 1e-6), against the closed forms -(3 + k) pi dgamma R / 2
# and -(1 - k)(5 + 3k) pi dgamma R / (2 (3 + k)). A continuum P beyond 1e-6 of its closed form,
# or a row's beyond its own error estimate, fails the job (a few seconds).
echo "== graded media: the pull-off against the grading exponent" >&2
exponents="0,0.1,0.2,0.25,0.3,0.4,0.5,0.6,0.7,0.75,0.8,0.9"
for control in fixed-load fixed-grips; do
  held=(--set "loading.normal={control=\"$control\"}")
  "$mdrsim" sweep scenes/graded/graded_parabola.toml --vary "material.grading.exponent=$exponents" \
    "${held[@]}" --csv "$results/graded_${control/-/_}.csv" --force --threads "$threads" \
    --log-level error
  "$mdrsim" sweep scenes/graded/graded_parabola.toml --vary "material.grading.exponent=$exponents" \
    "${held[@]}" --set 'solver={method="event"}' --set 'discretization={rtol=1e-6}' \
    --csv "$results/graded_row_${control/-/_}.csv" --force --threads "$threads" --log-level error
done
echo
"$py" scripts/plot_graded.py --results "$results"

# Beyond the paper: viscoelastic springs (docs/viscoelastic.md). A parabola pressed at constant
# speed into a standard linear solid and withdrawn until separation, its force against time
# beside Lee-Radok's and Ting's closed forms (computed in the script); a force beyond the row's
# stated error (2 / N of F(t_m)) or a separation time beyond 1e-3 t_m fails the job (a second).
echo "== viscoelastic springs: Lee-Radok and Ting" >&2
"$py" scripts/plot_viscoelastic.py --results "$results" --mdrsim "$mdrsim"

# Pull-off against speed (docs/rate_law.md, docs/viscoelastic.md): the rate law of the edge, the
# peak tension of a parabola retracted from JKR's zero-force state against beta, n = 1 and 1/2,
# two sweeps of the continuum route beside the front's ODE solved in the script (solve_ivp, rtol
# 1e-10), JKR's slow limit and the fast asymptote (an engine point beyond 1e-6 of the ODE fails
# the job); and a Prony solid's pull-off against the press-and-withdraw speed on the row, between
# its slow (JKR of E_inf, dgamma E_0 / E_inf) and fast (JKR of E_0) limits (beyond the row's
# O(1/N) bound of either, or not monotone, fails the job).
echo "== pull-off against speed: the rate law of the edge and a Prony solid" >&2
"$py" scripts/plot_rate_law_speed.py --results "$results" --mdrsim "$mdrsim"

echo "== comparison with the paper's closed forms" >&2
"$py" scripts/comparison_table.py --results "$results" --scenes scenes

# Speed against accuracy: one CSV row per method, springs and increment, the
# chart, and the targets checked on this machine (MET/MISS lines). An accuracy MISS (a wrong
# number) fails the job; a speed MISS, declared only after the target was measured three
# times, is reported and does not: a busy machine must not fail the main job. The chart is
# drawn either way.
echo "== speed against accuracy (bench/, about 15 s)" >&2
echo
bench_status=0
"$build_dir/bench/mdrsim_accuracy" --out "$results/speed_accuracy.csv" || bench_status=$?
"$py" scripts/plot_speed_accuracy.py --csv "$results/speed_accuracy.csv" --out "$results"

# The shorthand against its equal three-stage program on Fig. 2: the ratios are
# reported, a disagreement of the two engines (a DIFF line) fails the job. All the cases:
# build/bench/mdrsim_engines --repeats 5 --out engines.csv (a few minutes).
echo "== the shorthand against its equal program (bench/engines_bench.cpp, Fig. 2, a few s)" >&2
echo
"$build_dir/bench/mdrsim_engines" --case fig2 --out "$results/engines_fig2.csv" || bench_status=1
exit "$bench_status"
