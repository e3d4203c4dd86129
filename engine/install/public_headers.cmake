# The stable API: the headers `cmake --install` puts under include/mdrsim/, as paths from the
# repository root (the installed tree keeps them, so that an include reads the same in-tree
# and downstream). A downstream part needs its interface and registry; a downstream program
# the registries, the scene, the run and the observers. The set is closed: every header here
# includes only the standard library, the public dependencies (fmt, nlohmann_json) and headers
# of this list; tests/install/check_public_headers.cmake checks that, by compiling each one on
# its own against the installed tree, and lists every header left out.
set(MDRSIM_PUBLIC_HEADERS
    # vocabulary of the parts: material and interface properties, parameters, the registry
    engine/base/material.hpp
    engine/base/radial_adhesion.hpp
    engine/base/hess_scale.hpp
    engine/base/parameters.hpp
    engine/base/part_registry.hpp
    engine/base/pull_off_scales.hpp
    # what is zero on a run (RowSpec::zero of engine/pull_off/pull_off.hpp: the engine's own use)
    engine/base/zero_scale.hpp
    # the part interfaces and their registries
    profiles/profile.hpp
    profiles/profile_registry.hpp
    detachment/criterion.hpp
    detachment/criterion_registry.hpp
    controllers/controller.hpp
    controllers/controller_registry.hpp
    friction/friction_law.hpp
    friction/friction_law_registry.hpp
    # scenes: the registries a scene draws from, the document, the built scene, bad input
    engine/scene/registries.hpp
    engine/scene/scene_document.hpp
    engine/scene/scene.hpp
    engine/scene/program.hpp
    engine/scene/route_plan.hpp
    engine/model/friction_settings.hpp
    engine/model/graded_image.hpp
    engine/model/front_speed_law.hpp
    engine/scene/scene_error.hpp
    # the run and its result
    engine/run/run_scene.hpp
    engine/pull_off/pull_off.hpp
    engine/result/run_result.hpp
    engine/result/program_records.hpp
    engine/result/stop_reason.hpp
    engine/result/run_counts.hpp
    engine/model/contact_snapshot.hpp
    engine/model/jkr_scales.hpp
    engine/model/dimensionless_scales.hpp
    # events and observers
    engine/events/event.hpp
    engine/events/event_format.hpp
    engine/events/observer.hpp
    engine/events/event_recorder.hpp
    engine/events/log_observer.hpp
    engine/events/program_version.hpp
    # the stock outputs
    engine/output/trajectory_csv.hpp
    engine/output/result_json.hpp)
