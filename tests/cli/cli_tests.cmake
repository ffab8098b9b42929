# spec/cli.md: exit 0 on success, 2 for bad input with a one-line reason naming file and place,
# 1 for other failures.
set(expect ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_exit.cmake)
set(cli_dir ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set(out ${WALKRAD_TEST_OUTPUT})

function(walkrad_cli_test name exit)
  cmake_parse_arguments(T "" "STDERR;STDOUT;FILE;NO_FILE;JSON" "ARGS;JSON_NUMBERS" ${ARGN})
  # add_test splits on ';', so the command's words travel joined by '|'.
  string(JOIN "|" words $<TARGET_FILE:walkrad> ${T_ARGS})
  set(defs -DEXIT=${exit} "-DCOMMAND=${words}")
  if(T_JSON_NUMBERS)
    string(JOIN "|" numbers ${T_JSON_NUMBERS})
    list(APPEND defs "-DJSON_NUMBERS=${numbers}")
  endif()
  foreach(pair STDERR=STDERR_REGEX STDOUT=STDOUT_REGEX FILE=EXPECT_FILE NO_FILE=EXPECT_NO_FILE JSON=JSON_FILE)
    string(REPLACE "=" ";" pair ${pair})
    list(GET pair 0 option)
    list(GET pair 1 variable)
    if(T_${option})
      list(APPEND defs "-D${variable}=${T_${option}}")
    endif()
  endforeach()
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${expect})
  set_tests_properties(cli.${name} PROPERTIES ENVIRONMENT LP_NUM_THREADS=1)
endfunction()

walkrad_cli_test(help 0 ARGS --help STDOUT "render.*view")
walkrad_cli_test(render_help 0 ARGS render --help STDOUT "--wireframe")
walkrad_cli_test(no_subcommand 2 ARGS STDERR "^walkrad: ")
walkrad_cli_test(unknown_flag 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png --shiny
                 STDERR "^walkrad: .*--shiny")
walkrad_cli_test(bad_width 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png --width 0
                 STDERR "^walkrad: .*width")
walkrad_cli_test(missing_scene 2 ARGS render ${out}/no-such-scene.json --out ${out}/missing.png
                 STDERR "no-such-scene.json: cannot read the file" NO_FILE ${out}/missing.png)
walkrad_cli_test(non_convex_profile 2 ARGS render ${cli_dir}/bad_profile.json --out ${out}/bad.png
                 STDERR "bad_profile.json: objects\\[0\\]\\.solids\\[0\\]\\.profile: profile is not convex$"
                 NO_FILE ${out}/bad.png)
walkrad_cli_test(truncated_scene 2 ARGS render ${cli_dir}/truncated.json --out ${out}/trunc.png
                 STDERR "truncated.json:4:1: not valid JSON")
walkrad_cli_test(unknown_camera 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cam.png --camera nope
                 STDERR "cornell.json: cameras: no camera named \"nope\"")
walkrad_cli_test(view_bad_scene 2 ARGS view ${cli_dir}/bad_profile.json STDERR "profile is not convex")
walkrad_cli_test(nothing_to_write 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json STDERR "--out")
walkrad_cli_test(unwritable_output 1 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/no/such/dir/x.png
                 STDERR "x.png: cannot create")
# Every numeric option of every subcommand refuses NaN and infinities, in any spelling, and values
# beyond its limits (for integers: negative, fractional, overflowing): exit 2, one line naming
# the option. Each entry: SUBCOMMAND OPTION OUT-OF-RANGE-VALUE...; `check` takes no number.
# cli.numbers_all_tried fails when `--help` lists a numeric option missing here.
set(number_inputs_render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png)
set(number_inputs_view ${PROJECT_SOURCE_DIR}/assets/cornell.json)
set(number_inputs_mesh ${cli_dir}/wall_with_window.json)
set(number_inputs_export ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.glb)
set(numbers_tried)
foreach(entry
    "render --width 0 16385 99999999999999999999 1e3" "render --height -1 16385 1.5" "render --exposure 0 1e13 1e999"
    "render --patch-size 0 -1 2e6" "render --converge 0 1.5" "render --max-shots -1 99999999999999999999 0x10"
    "render --threads 0 65" "render --adapt-threshold 0 11" "render --min-element 0 2e6"
    "view --patch-size 0" "view --width 63" "view --height 16385" "view --frames -1 2147483648" "view --threads 65"
    "view --adapt-threshold -1" "view --min-element -1"
    "mesh --patch-size 0 1e-400" "mesh --repeat 0 100001"
    "export --exposure -1" "export --patch-size 1e7" "export --converge 2" "export --max-shots -1" "export --threads 0"
    "export --adapt-threshold 10.5" "export --min-element 0")
  separate_arguments(entry)
  list(POP_FRONT entry command option)
  list(APPEND numbers_tried "${command} ${option}")
  string(JOIN "|" prefix $<TARGET_FILE:walkrad> ${command} ${number_inputs_${command}})
  string(JOIN "|" values nan NaN inf INF -inf ${entry})
  string(REPLACE "--" "" name ${option})
  add_test(NAME cli.numbers.${command}.${name}
           COMMAND ${CMAKE_COMMAND} "-DPREFIX=${prefix}" -DOPTION=${option} "-DVALUES=${values}" -P ${cli_dir}/refuses_values.cmake)
endforeach()
string(JOIN "|" numbers_tried ${numbers_tried})
add_test(NAME cli.numbers_all_tried
         COMMAND ${CMAKE_COMMAND} -DWALKRAD=$<TARGET_FILE:walkrad> "-DSUBCOMMANDS=render|view|mesh|check|export"
                 "-DLISTED=${numbers_tried}" -P ${cli_dir}/numbers_listed.cmake)
walkrad_cli_test(render_all_outputs 0
                 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cli-cornell.png
                      --linear ${out}/cli-cornell.pfm --stats ${out}/cli-cornell.json --width 200 --height 150 --wireframe
                 FILE ${out}/cli-cornell.pfm)

# The solve before the picture: stopped by --max-shots, or by --converge (progress on stdout).
walkrad_cli_test(render_max_shots 0 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cli-max-shots.png
                 --max-shots 20 --width 64 --height 48 STDOUT "solved in [0-9.e-]+ s: 20 shots, unshot")
walkrad_cli_test(render_converge 0 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cli-converge.png
                 --converge 0.3 --width 64 --height 48 STDOUT "solved in [0-9.e-]+ s: [0-9]+ shots, unshot (30|(2[0-9]|1[0-9]|[0-9])(\\.[0-9]+)?)%")
walkrad_cli_test(render_bad_converge 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png --converge 2
                 STDERR "converge")
walkrad_cli_test(render_zero_converge 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png --converge 0
                 STDERR "converge")
walkrad_cli_test(render_out_is_a_folder 1 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}
                 STDERR "cannot create: Is a directory")
walkrad_cli_test(render_missing_scene_first 2 ARGS render ${out}/no-such-scene.json --out ${out}/no/such/dir/x.png
                 STDERR "no-such-scene.json")

# walkrad mesh: polygon cases and scenes.
walkrad_cli_test(mesh_polygon_case 0 ARGS mesh ${cli_dir}/wall_with_window.json --stats ${out}/mesh-wall.json --dump ${out}/mesh-wall-dump.json
                 STDOUT "0 T-vertices" FILE ${out}/mesh-wall-dump.json)
walkrad_cli_test(mesh_scene 0 ARGS mesh ${PROJECT_SOURCE_DIR}/assets/cornell.json --patch-size 100 --repeat 2 STDOUT "elements .*quads")
walkrad_cli_test(mesh_hole_outside 2 ARGS mesh ${cli_dir}/hole_outside.json STDERR "hole_outside.json: holes\\[0\\]: hole is not strictly inside")
walkrad_cli_test(mesh_no_patch_size 2 ARGS mesh ${cli_dir}/no_patch_size.json STDERR "no_patch_size.json: patch_size: missing required field")
walkrad_cli_test(mesh_bad_repeat 2 ARGS mesh ${cli_dir}/wall_with_window.json --repeat 0 STDERR "^walkrad: .*repeat")

# --patch-size goes through the scene file's limit (no more than 100,000 patches along the
# extent) for scenes, glTF models and polygon cases, at once rather than after meshing for ever.
walkrad_cli_test(render_tiny_patch_size 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/tiny.png --patch-size 1e-12
                 STDERR "cornell.json: --patch-size: patch size too small for the scene" NO_FILE ${out}/tiny.png)
walkrad_cli_test(view_tiny_patch_size 2 ARGS view ${PROJECT_SOURCE_DIR}/assets/cornell.json --patch-size 1e-12
                 STDERR "cornell.json: --patch-size: patch size too small for the scene")
walkrad_cli_test(mesh_tiny_patch_size 2 ARGS mesh ${PROJECT_SOURCE_DIR}/assets/kitchen.json --patch-size 1e-12
                 STDERR "kitchen.json: --patch-size: patch size too small for the scene")
walkrad_cli_test(export_gltf_tiny_patch_size 2 ARGS export ${cli_dir}/no_light.gltf --out ${out}/tiny.glb --patch-size 1e-12
                 STDERR "no_light.gltf: --patch-size: patch size too small for the scene" NO_FILE ${out}/tiny.glb)
walkrad_cli_test(mesh_polygon_tiny_patch_size 2 ARGS mesh ${cli_dir}/wall_with_window.json --patch-size 1e-12
                 STDERR "wall_with_window.json: --patch-size: patch size too small for the scene")
walkrad_cli_test(mesh_polygon_file_tiny_patch_size 2 ARGS mesh ${cli_dir}/tiny_patch_size.json
                 STDERR "tiny_patch_size.json: patch_size: patch size too small for the scene")
# Within that limit, a mesh past the mesher's work limit (mesher.h) is refused before it is made,
# naming the surface: a patch size just over the scene limit, for a polygon case and a scene.
walkrad_cli_test(mesh_polygon_patch_size_near_limit 2 ARGS mesh ${cli_dir}/wall_with_window.json --patch-size 0.0025
                 STDERR "wall_with_window.json: outer: mesh too large")
walkrad_cli_test(render_patch_size_near_limit 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/near.png --patch-size 0.006
                 STDERR "cornell.json: objects\\[0\\]\\.solids\\[0\\]: mesh too large" NO_FILE ${out}/near.png)
# Issue 19's thin polygons: a needle 0.375 wide and 1.7 million long is refused as its tree
# reaches the limit (it meshed for over 20 s); a comb of 50 teeth meshes without T-vertices or
# elements below the angle bound (it had 42, and an angle of 0 degrees).
walkrad_cli_test(mesh_needle_refused 2 ARGS mesh ${cli_dir}/needle.json STDERR "needle.json: outer: mesh too large")
# Vertices 1e-10 apart 1e5 from the origin: closer than the mesh's points resolve there.
walkrad_cli_test(mesh_hair_apart_far 2 ARGS mesh ${cli_dir}/hair_apart_far.json
                 STDERR "hair_apart_far.json: outer: detail finer than the coordinates resolve")
walkrad_cli_test(mesh_comb 0 ARGS mesh ${cli_dir}/comb50.json STDOUT " 0 T-vertices, smallest angle 21.80 deg \\(0 elements below")

# --move: after converging, an object moves through the edit path and the light converges again.
# Its statistics give each move's figures, as README lists them.
walkrad_cli_test(render_move 0 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cli-move.png
                 --converge 0.3 --width 64 --height 48 --move "short block:40,0,-20" --move "tall block:0,10,0"
                 --stats ${out}/cli-move.json
                 STDOUT "move 1 converged in [0-9.e-]+ s: [0-9]+ shots.*move 2 converged"
                 JSON ${out}/cli-move.json
                 JSON_NUMBERS moves.0.remesh_ms moves.0.ui_ms moves.0.first_update_ms moves.0.converge_ms moves.0.elements_changed
                              moves.0.corrections moves.0.windowed_corrections moves.1.converge_ms)
# A move whose footprint leaves a strip of floor 3 um wide 900 km from the origin, finer than the
# mesher resolves there: exit 2 naming the option and the floor; no picture is written.
walkrad_cli_test(render_move_sliver 2 ARGS render ${cli_dir}/far_room_box.json --out ${out}/cli-move-sliver.png
                 --converge 0.5 --width 32 --height 24 --move "box:-0.399997,0,0"
                 STDERR "^walkrad render: --move \"box:-0.399997,0,0\": .*far_room_box.json: objects\\[0\\]\\.solids\\[0\\]: detail finer than the coordinates resolve.*: moving \"box\" there, the bottom of \"room\": "
                 NO_FILE ${out}/cli-move-sliver.png)
walkrad_cli_test(render_move_fixed 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "room:1,0,0" STDERR "--move \"room:1,0,0\": \"room\" is not movable")
walkrad_cli_test(render_move_unknown 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "sofa:1,0,0" STDERR "no object \"sofa\"")
walkrad_cli_test(render_move_two_numbers 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "tall block:1,0" STDERR "expected three numbers")
walkrad_cli_test(render_move_not_a_number 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "tall block:1,x,0" STDERR "expected three numbers")
# --move keeps the object within the scene limits (coordinates within 1e6, as scene files): not a
# number, beyond the limits, or there after the moves before it, it is exit 2 naming the option.
foreach(offset nan inf -inf NaN 1e7 1e308 -1e308 1e999)
  walkrad_cli_test(render_move_refused_${offset} 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                   --move "short block:0,${offset},0" STDERR "^walkrad render: --move \"short block:0,${offset},0\": ")
endforeach()
walkrad_cli_test(render_move_beyond_limits 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "short block:1e7,0,0"
                 STDERR "--move \"short block:1e7,0,0\": puts \"short block\" at \\(1e\\+07, 0, 0\\), beyond the scene limits")
walkrad_cli_test(render_moves_add_up_beyond_limits 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --move "short block:6e5,0,0" --move "tall block:6e5,0,0" --move "short block:6e5,0,0"
                 STDERR "--move \"short block:6e5,0,0\": puts \"short block\" at \\(1.2e\\+06, 0, 0\\)")
# Adaptive refinement: on with its flags (the stats count its passes), a bad value or both on
# and off is exit 2 naming the option.
walkrad_cli_test(render_adaptive 0 ARGS render ${PROJECT_SOURCE_DIR}/assets/box-on-floor.json --out ${out}/cli-adaptive.png
                 --width 160 --height 120 --converge 0.05 --adapt-threshold 0.3 --min-element 0.2 --stats ${out}/cli-adaptive.json
                 FILE ${out}/cli-adaptive.json)
walkrad_cli_test(render_adaptive_zero_threshold 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --adapt-threshold 0 STDERR "adapt-threshold")
walkrad_cli_test(render_adaptive_on_and_off 2 ARGS render ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.png
                 --adapt-threshold 0.2 --no-adapt STDERR "no-adapt")

# walkrad check: findings are not failures (exit 0); a file that cannot be read or breaks the
# spec is exit 2, as for the other subcommands.
walkrad_cli_test(check_help 0 ARGS check --help STDOUT "--json")
walkrad_cli_test(check_cornell 0 ARGS check ${PROJECT_SOURCE_DIR}/assets/cornell.json --json ${out}/check-cornell.json
                 STDOUT "cornell.json: objects\\[0\\]\\.solids\\[0\\] \\(room, [^)]*\\) at \\([^)]*\\): warning: open edges: an opening of 4 edges.*; walkrad: nothing: .*18 faces checked in [0-9.e-]+ ms: 1 finding \\(1 open edges\\)"
                 FILE ${out}/check-cornell.json)
# A scene with one of most defects: two boxes in one place, a post through a table, a one-sided
# partition, a crate without a top.
walkrad_cli_test(check_defects 0 ARGS check ${cli_dir}/model_defects.json
                 STDOUT "37 faces checked in [0-9.e-]+ ms: 21 findings \\(6 duplicate face, 8 interpenetrating faces, 1 open edges, 6 back seen\\)")
walkrad_cli_test(check_clean 0 ARGS check ${PROJECT_SOURCE_DIR}/assets/furnace.json STDOUT "6 faces checked in [0-9.e-]+ ms: 0 findings")
walkrad_cli_test(check_missing 2 ARGS check ${out}/no-such-model.json STDERR "no-such-model.json: cannot read the file")
walkrad_cli_test(check_truncated 2 ARGS check ${cli_dir}/truncated.json STDERR "truncated.json:4:1: not valid JSON")
walkrad_cli_test(check_non_convex 2 ARGS check ${cli_dir}/bad_profile.json --json ${out}/check-bad.json
                 STDERR "bad_profile.json: objects\\[0\\]\\.solids\\[0\\]\\.profile: profile is not convex$" NO_FILE ${out}/check-bad.json)
walkrad_cli_test(check_unwritable_json 1 ARGS check ${PROJECT_SOURCE_DIR}/assets/cornell.json --json ${out}/no/such/dir/c.json
                 STDERR "c.json: cannot create")

# walkrad export: the solved scene as glTF; bad input is exit 2, an unwritable output 1.
walkrad_cli_test(export_help 0 ARGS export --help STDOUT "--exposure")
walkrad_cli_test(export_glb 0 ARGS export ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/cli-cornell.glb --max-shots 30
                 STDOUT "solved in [0-9.e-]+ s: 30 shots.*cli-cornell.glb: [0-9]+ bytes, [0-9]+ triangles, [0-9]+ vertices, exposure [0-9.e-]+"
                 FILE ${out}/cli-cornell.glb)
walkrad_cli_test(export_gltf 0 ARGS export ${PROJECT_SOURCE_DIR}/assets/box-on-floor.json --out ${out}/cli-box.gltf --max-shots 10
                 --exposure 2 --quiet FILE ${out}/cli-box.gltf)
walkrad_cli_test(export_no_out 2 ARGS export ${PROJECT_SOURCE_DIR}/assets/cornell.json STDERR "^walkrad: .*--out")
walkrad_cli_test(export_bad_extension 2 ARGS export ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/lit.obj
                 STDERR "--out \".*lit.obj\": expected a .glb or .gltf file name" NO_FILE ${out}/lit.obj)
walkrad_cli_test(export_missing_scene 2 ARGS export ${out}/no-such-scene.json --out ${out}/no/such/dir/lit.glb
                 STDERR "no-such-scene.json: cannot read the file")
walkrad_cli_test(export_truncated 2 ARGS export ${cli_dir}/truncated.json --out ${out}/trunc.glb
                 STDERR "truncated.json:4:1: not valid JSON" NO_FILE ${out}/trunc.glb)
walkrad_cli_test(export_unwritable 1 ARGS export ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/no/such/dir/lit.glb
                 STDERR "lit.glb: cannot create")
walkrad_cli_test(export_bad_exposure 2 ARGS export ${PROJECT_SOURCE_DIR}/assets/cornell.json --out ${out}/x.glb --exposure -1
                 STDERR "^walkrad: .*exposure")

walkrad_cli_test(truncated_gltf 2 ARGS render ${cli_dir}/truncated.gltf --out ${out}/trunc-gltf.png
                 STDERR "truncated.gltf: not a readable glTF 2.0 model: .*parse error" NO_FILE ${out}/trunc-gltf.png)
walkrad_cli_test(units_for_scene_file 2 ARGS mesh ${PROJECT_SOURCE_DIR}/assets/cornell.json --units cm
                 STDERR "cornell.json: --units: this option applies to glTF models only")
# A model without lamps renders (black), saying why and how to light it.
walkrad_cli_test(gltf_without_light 0 ARGS render ${cli_dir}/no_light.gltf --out ${out}/no-light.png --quiet
                 STDERR "no_light.gltf: nothing emits light, so the picture is black \\(give a material an emission, or a sky, in its .walkrad.json sidecar\\)"
                 FILE ${out}/no-light.png)

# check and export take glTF models as the other subcommands do: check looks at each triangle
# (the floor's two), export bakes the model's light.
walkrad_cli_test(check_gltf 0 ARGS check ${cli_dir}/no_light.gltf STDOUT "no_light.gltf: 2 faces checked in [0-9.e-]+ ms: 0 findings")
walkrad_cli_test(check_truncated_gltf 2 ARGS check ${cli_dir}/truncated.gltf STDERR "truncated.gltf: not a readable glTF 2.0 model")
walkrad_cli_test(units_for_polygon_case 2 ARGS mesh ${cli_dir}/wall_with_window.json --units cm
                 STDERR "wall_with_window.json: --units: this option applies to glTF models only")
walkrad_cli_test(check_units_for_scene_file 2 ARGS check ${PROJECT_SOURCE_DIR}/assets/cornell.json --units cm
                 STDERR "cornell.json: --units: this option applies to glTF models only")
walkrad_cli_test(export_gltf_model 0 ARGS export ${cli_dir}/no_light.gltf --out ${out}/no-light-export.glb --quiet
                 FILE ${out}/no-light-export.glb)

# A glTF model reads only regular files inside its own folder (README, "Models from Blender");
# every other URI is exit 2 naming it, and export writes nothing.
walkrad_cli_test(gltf_uri_outside 2 ARGS render ${cli_dir}/uri_outside.gltf --out ${out}/uri-outside.png
                 STDERR "uri_outside.gltf: buffers\\[0\\]\\.uri: glTF URI leads outside the model's folder: \"\\.\\./CMakeLists\\.txt\"$"
                 NO_FILE ${out}/uri-outside.png)
walkrad_cli_test(export_gltf_uri_outside 2 ARGS export ${cli_dir}/uri_outside.gltf --out ${out}/uri-outside.glb
                 STDERR "uri_outside.gltf: buffers\\[0\\]\\.uri: glTF URI leads outside" NO_FILE ${out}/uri-outside.glb)
walkrad_cli_test(gltf_uri_absolute 2 ARGS mesh ${cli_dir}/uri_absolute.gltf
                 STDERR "uri_absolute.gltf: buffers\\[0\\]\\.uri: glTF URI is an absolute path \\(only files in the model's folder are read\\): \"/etc/passwd\"$")
walkrad_cli_test(gltf_uri_folder 2 ARGS check ${cli_dir}/uri_folder.gltf
                 STDERR "uri_folder.gltf: buffers\\[0\\]\\.uri: not a regular file: \"\\.\": a folder$")
walkrad_cli_test(gltf_data_uri_length 2 ARGS mesh ${cli_dir}/data_uri_length.gltf
                 STDERR "data_uri_length.gltf: buffers\\[0\\]\\.uri: glTF buffer's data is not byteLength bytes long: \"data:application/octet-stream;base64,[^\"]*\": decodes to 60 bytes, byteLength says 64$")
# Input files are regular files: a device is refused unread (/dev/zero never ends).
walkrad_cli_test(mesh_device_input 2 ARGS mesh /dev/zero STDERR "^/dev/zero: not a regular file: a device$")
# A number too large for a double is placed by line and column, in scenes and polygon cases.
walkrad_cli_test(huge_number 2 ARGS render ${cli_dir}/huge_number.json --out ${out}/huge.png
                 STDERR "huge_number.json:3:31: not a finite number: 1e999 is too large for a double$" NO_FILE ${out}/huge.png)
walkrad_cli_test(mesh_huge_number 2 ARGS mesh ${cli_dir}/huge_polygon.json
                 STDERR "huge_polygon.json:2:22: not a finite number: 1e400 is too large for a double$")
