# Labels every gtest case `quick` or `slow` (ctest -L quick: the everyday subset), read by ctest
# after the discovered tests (tests/CMakeLists.txt appends it to TEST_INCLUDE_FILES, with
# mdrsim_test_lists naming each executable's TEST_LIST variable).
#
# `slow`: the cases measured at more than about 1.5 s each (ctest -j2 --output-junit on 2 shared
# cores); everything else, a new test too, is `quick`. `ctest -L quick` then runs in
# well under two minutes on 2 cores; plain ctest still runs everything. A name matches if one
# of these regular expressions finds it (ctest's full name: Suite.Case, or
# Instance/Suite.Case/Param  # GetParam() = ... for a parameterized case).
set(mdrsim_slow_tests
    "^ViscoelasticFrictionRows\\.RichardsonCombinesTheTangentialWorkAndFriction$"  # 6 s: rows of 4000 and 8000 springs (rebinding scans O(N) an event)
    # rows of up to 2^25 springs on the plain route: 150 s and 12 s
    "^RandomSet/RtolGuarantee\\.WithinRtolOfTheContinuum/rtol1e[46]_none"
    "^RandomScenes\\.PlainRowAgreesWithTheReference$"  # 7.5 s
    "^EdgeCasesLarge\\."  # 10^7 springs: 4 s
    # the Dugdale row on the sphere and a power law: a quadrature per let-go
    "^DugdaleRows\\.RowsConvergeOnQuadratureProfiles$"
    "^DugdaleRows\\.RichardsonAndRtolMeetTheContinuumOnQuadratureProfiles$"
    "^Determinism\\.SameSceneTwiceGivesByteIdenticalJson$"  # 8 s
    "^PlotProgram\\.AJumpOffUnderFixedLoadDoesNotSetTheRange$"  # 5 s (matplotlib)
    "^Cli\\.EveryKeyOfTheSceneWrongThroughSet$"  # 3.5 s
    "^Cli\\.TabulatedProfileFromAnEndlessDevice$"  # 2.5 s
    "^ModeDependentCriterion\\.MatchesTheLongDoubleRootOverLambdaAngleAndScale$"  # 3 s
    "^Sweep\\.KilledMidwayThenResumedEqualsAnUninterruptedSweep$"  # 3 s
    "^Sweep\\.InterruptedByCtrlCExits130WithWholeRows$"  # 1.7 s
    "^StatusMargin\\.TheStatusDoesNotDependOnRtol$"  # 1.5 s
    "^Provenance\\.ItsSceneRunAgainGivesIdenticalNumbers$"  # 1.4 s
    "^RoughAdhesion\\.FrontPinnedAtAStepFarOutside$"  # 4.9 s: rows of 2^19 springs
    "^ProgramRtolPinned\\.RebindingReloadWorkMeetsRtolAgainstItsClosedForm$"  # 3 s: rows of 2^24
    "^ViscoelasticRows\\.RtolStopsWhereRoundingLimitsTheCriticalPoint$"  # 1.7 s: rows of 2^18
    "^RouteAgreement\\."  # 120 scenes on both routes, the row at rtol 1e-8: 5 s
    # 100 seeds of a Maugis fit of both segments a case: 3-20 s
    "^Cases/MaugisBothSynthetic\\."
    # the short-baseline warning over the design table: 8 lever curves and 4 joint fits a case
    "^Designs/MaugisBothWarnings\\."
    # the point-force kernel over a punch from 25 points outside it: 7.6 s
    "^GradedConstants\\.PunchOuterSurfaceMatchesTheKernelQuadrature$")

# Also labelled `unsanitized`: cases that run the paths other cases cover, on bigger rows or
# more scenes, 10 to 20 times slower under AddressSanitizer (or a plot through matplotlib). scripts/test.sh leaves them
# out of its sanitizer stage (ctest -LE unsanitized) and runs them in its first stage only.
set(mdrsim_unsanitized_tests
    "^RoughAdhesion\\.FrontPinnedAtAStepFarOutside$"
    "^ProgramRtolPinned\\."
    "^RandomSet/RtolGuarantee\\.WithinRtolOfTheContinuum/rtol1e[46]_none"
    "^RandomSet/RtolGuarantee\\.WithinRtolOfTheContinuum/rtol1e6_"
    "^RandomScenes\\.PlainRowAgreesWithTheReference$"
    "^EdgeCasesLarge\\."
    "^Determinism\\.SameSceneTwiceGivesByteIdenticalJson$"
    "^PlotProgram\\."
    "^StatusMargin\\.TheStatusDoesNotDependOnRtol$"
    "^Provenance\\.ItsSceneRunAgainGivesIdenticalNumbers$"
    "^RouteAgreement\\."
    "^ViscoelasticRows\\.RtolStopsWhereRoundingLimitsTheCriticalPoint$"
    # the Maugis fits' recovery over 100 seeds (MaugisFit's single fits run the same code under
    # the sanitizers): 30-140 s a case there
    "^Cases/MaugisBothSynthetic\\."
    "^Cases/MaugisApproachSynthetic\\."
    # the kernel quadrature FlatPunchMatchesTheKernelQuadrature runs there, from outside the disk
    "^GradedConstants\\.PunchOuterSurfaceMatchesTheKernelQuadrature$")

set(mdrsim_quick_names)
set(mdrsim_slow_names)
set(mdrsim_quick_unsanitized_names)
set(mdrsim_slow_unsanitized_names)
# Each list as one regular expression: its patterns as alternatives.
list(JOIN mdrsim_slow_tests "|" mdrsim_slow_regex)
list(JOIN mdrsim_unsanitized_tests "|" mdrsim_unsanitized_regex)
foreach(list IN LISTS mdrsim_test_lists)
  foreach(name IN LISTS ${list})
    set(slow FALSE)
    set(unsanitized FALSE)
    if(name MATCHES "${mdrsim_slow_regex}")
      set(slow TRUE)
    endif()
    if(name MATCHES "${mdrsim_unsanitized_regex}")
      set(unsanitized TRUE)
    endif()
    if(slow AND unsanitized)
      list(APPEND mdrsim_slow_unsanitized_names "${name}")
    elseif(slow)
      list(APPEND mdrsim_slow_names "${name}")
    elseif(unsanitized)
      list(APPEND mdrsim_quick_unsanitized_names "${name}")
    else()
      list(APPEND mdrsim_quick_names "${name}")
    endif()
  endforeach()
endforeach()
if(mdrsim_quick_names)
  set_tests_properties(${mdrsim_quick_names} PROPERTIES LABELS quick)
endif()
if(mdrsim_slow_names)
  # COST: ctest -j starts the costliest first (a fresh build has no timings of its own), so
  # that a long case runs beside the many short ones instead of alone at the end.
  set_tests_properties(${mdrsim_slow_names} PROPERTIES LABELS slow COST 100)
endif()
if(mdrsim_quick_unsanitized_names)
  set_tests_properties(${mdrsim_quick_unsanitized_names} PROPERTIES LABELS "quick;unsanitized")
endif()
if(mdrsim_slow_unsanitized_names)
  set_tests_properties(${mdrsim_slow_unsanitized_names} PROPERTIES LABELS "slow;unsanitized"
                                                                   COST 100)
endif()
