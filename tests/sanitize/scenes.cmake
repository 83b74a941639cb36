# A short headless run of every scene under AddressSanitizer + UBSan + LeakSanitizer, with the
# validation layer on (included by tests/CMakeLists.txt when VITRINE_SANITIZE is on). The scenes are
# the registry's: the list in cmake/Scenes.cmake.
set(sanitize_out ${CMAKE_BINARY_DIR}/sanitize-out)
file(MAKE_DIRECTORY ${sanitize_out})
set(vitrine_bin $<TARGET_FILE:vitrine>)
set(sanitize_scene_tests)
foreach(scene IN LISTS VITRINE_SCENES)
  add_test(NAME sanitize.scene.${scene} COMMAND ${VITRINE_SANITIZE_RUN} ${vitrine_bin} --headless --scene ${scene}
    --size 64x36 --frames 3 --validate --out ${sanitize_out}/${scene}.exr)
  list(APPEND sanitize_scene_tests sanitize.scene.${scene})
endforeach()
# Long enough for the worker and sound paths: neon's particle worker under a scripted drag that releases
# tubes, and bloom's phases with the offline audio engine rendering its bells to a WAV.
add_test(NAME sanitize.scene.neon_drag COMMAND ${VITRINE_SANITIZE_RUN} ${vitrine_bin} --headless --scene neon
  --size 64x36 --frames 60 --set chains=256 --validate --input ${CMAKE_CURRENT_SOURCE_DIR}/input/neon_drag.txt
  --events ${sanitize_out}/neon.jsonl --out ${sanitize_out}/neon_drag.exr)
add_test(NAME sanitize.scene.bloom_sound COMMAND ${VITRINE_SANITIZE_RUN} ${vitrine_bin} --headless --scene bloom
  --size 64x36 --frames 240 --set lattice=48 --validate --input ${CMAKE_CURRENT_SOURCE_DIR}/input/bloom_hold.txt
  --events ${sanitize_out}/bloom.jsonl --audio-out ${sanitize_out}/bloom.wav --out ${sanitize_out}/bloom_sound.exr)
set_tests_properties(${sanitize_scene_tests} sanitize.scene.neon_drag sanitize.scene.bloom_sound
  PROPERTIES LABELS sanitize TIMEOUT 600)
