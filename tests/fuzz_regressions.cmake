# The fuzzing findings of issue 10, run through the command line (inputs and what each broke:
# data/fuzz/README.md). Each must end in its expected exit status, an error naming the file
# where it fails, never a signal or a hang.
set(FUZZ ${CMAKE_CURRENT_SOURCE_DIR}/data/fuzz)
set(FUZZ_OUT ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
file(MAKE_DIRECTORY ${FUZZ_OUT})

# fuzz_test(NAME CODE TEXT ARGS...): objektiv ARGS exits with CODE and prints TEXT.
function(fuzz_test name code text)
  list(JOIN ARGN "$<SEMICOLON>" args)
  add_test(NAME fuzz_${name} COMMAND ${CMAKE_COMMAND} -DCMD=${OBJ}$<SEMICOLON>${args}
    -DEXPECT_CODE=${code} -DEXPECT_TEXT=${text} -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties(fuzz_${name} PROPERTIES TIMEOUT 60)
endfunction()

fuzz_test(texture_uv_huge 0 "NaN 0" render ${FUZZ}/03-texture-to-uv-huge.xml --spp 1 -o ${FUZZ_OUT}/03.exr)
fuzz_test(zmx_curv_infinity 1 "05-zmx-curv-infinity.zmx:11: 'INFINITY' is not a finite number"
  lens info ${FUZZ}/05-zmx-curv-infinity.zmx)
fuzz_test(png_header_12000 1 "06-png-header-12000x12000.png: cannot decode image"
  render ${FUZZ}/06-texture-scene.xml -o ${FUZZ_OUT}/06.exr)
fuzz_test(ply_bad_index 1 "07-ply-bad-index-segv.ply: face 1 has 0 corners (a face needs at least 3)"
  render ${FUZZ}/07-mesh-scene.xml -o ${FUZZ_OUT}/07.exr)
fuzz_test(ply_triangulate_assert 1 "08-ply-triangulate-assert.ply:83: '0.23' is not a list length"
  render ${FUZZ}/07-mesh-scene.xml -D meshfile=08-ply-triangulate-assert.ply -o ${FUZZ_OUT}/08.exr)
fuzz_test(ply_header_hang 1 "09-ply-truncated-header-hang.ply:14: a header line with a byte that is not printable ASCII"
  render ${FUZZ}/07-mesh-scene.xml -D meshfile=09-ply-truncated-header-hang.ply -o ${FUZZ_OUT}/09.exr)
fuzz_test(huge_vertex_area_light 1 "02-embree-assert-scene.xml:12: vertex 63 lies at (-0.523986, 9.22337e+18, 0.0906492)"
  render ${FUZZ}/02-embree-assert-scene.xml -o ${FUZZ_OUT}/02.exr)
# A 65536x65536 film (or 40000x30000) ended in std::bad_alloc with no message, or on a big
# machine would allocate and render: refused against the memory budget, --max-memory.
fuzz_test(film_over_budget 1 "cornell-box.xml:29: rendering 65536x65536 pixels needs 636 GiB, more than the memory budget of 16 GiB"
  render ${CORNELL} -D res=65536 -o ${FUZZ_OUT}/film.exr)
fuzz_test(film_budget_option 1 "rendering 64x64 pixels needs 0.000607 GiB, more than the memory budget of 0.0001 GiB"
  render ${CORNELL} -D res=64 --max-memory 0.0001 -o ${FUZZ_OUT}/film.exr)
fuzz_test(film_crop_within_budget 0 "4x4, 1 spp" render ${CORNELL} -D res=65536 --crop 0,0,4,4 --spp 1 -o ${FUZZ_OUT}/film.exr)
fuzz_test(film_budget_not_positive 2 "--max-memory" render ${CORNELL} --max-memory 0 -o ${FUZZ_OUT}/film.exr)
# OBJ values tinyobjloader read silently as 0 (or as no index): refused with their line.
fuzz_test(obj_word_for_number 1 "10-obj-word-for-number.obj:3: 'abc' in a vertex (v) is not a finite number"
  render ${FUZZ}/07-mesh-scene.xml -D meshtype=obj -D meshfile=10-obj-word-for-number.obj -o ${FUZZ_OUT}/10.exr)
fuzz_test(obj_bad_corner 1 "10-obj-bad-corner.obj:4: 'x3' is not a corner"
  render ${FUZZ}/07-mesh-scene.xml -D meshtype=obj -D meshfile=10-obj-bad-corner.obj -o ${FUZZ_OUT}/10.exr)
# A vertex row with two values ("-1 1-1") put the next row's 57-digit list length where
# Assimp read a count: 3.8 GB allocated (found by fuzz_mesh_ply). Records are one to a line
# (tests/test_ply.cpp); this file is now refused sooner, for its header's unprintable bytes.
fuzz_test(ply_list_length_oom 1 "11-ply-list-length-oom.ply:4: a header line with a byte that is not printable ASCII"
  render ${FUZZ}/07-mesh-scene.xml -D meshfile=11-ply-list-length-oom.ply -o ${FUZZ_OUT}/11.exr)
# BMPs of a few hundred bytes claiming 3493896x8 and 13107208x8 pixels: OpenImageIO's BMP
# reader allocated 2.7 and 10 GB for the claim (found by fuzz_image).
fuzz_test(bmp_claims_3493896x8 1 "12-bmp-claims-3493896x8.bmp: cannot read image: its header claims 3493896x8 pixels, more than a 189-byte BMP file can hold"
  render ${FUZZ}/06-texture-scene.xml -D texfile=12-bmp-claims-3493896x8.bmp -o ${FUZZ_OUT}/12a.exr)
fuzz_test(bmp_claims_13107208x8 1 "12-bmp-claims-13107208x8.bmp: cannot read image: its header claims 13107208x8 pixels"
  render ${FUZZ}/06-texture-scene.xml -D texfile=12-bmp-claims-13107208x8.bmp -o ${FUZZ_OUT}/12b.exr)
# A run-length-coded BMP of 1094 bytes claiming 50000x50000 pixels: OpenImageIO's reader
# decodes it inside open(), into a buffer of width x height bytes multiplied in an int, which
# overflowed to a negative size: std::length_error, a crash (found by fuzz_image in CI). The
# claim is now checked before the file is opened.
fuzz_test(bmp_rle_claims_50000x50000 1 "13-bmp-rle8-50000x50000.bmp: the image is 50000x50000, more than the limit of 268435456 pixels"
  render ${FUZZ}/06-texture-scene.xml -D texfile=13-bmp-rle8-50000x50000.bmp -o ${FUZZ_OUT}/13.exr)
# An EXR of 1205 bytes claiming 16777220x2 pixels (within the pixel and byte limits):
# OpenImageIO's reader decodes 256 rows at a time into a buffer of its own and asked for
# 51 GB (found by fuzz_image in CI). Rows that wide are refused before reading.
fuzz_test(exr_rows_too_wide 1 "14-exr-2x16777220.exr: the image's rows are too wide to read"
  render ${FUZZ}/06-texture-scene.xml -D texfile=14-exr-2x16777220.exr -o ${FUZZ_OUT}/14.exr)
