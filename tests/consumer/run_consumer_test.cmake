# Installs the build tree into a scratch prefix, then configures, builds and
# runs a tiny downstream project that uses find_package(igaprep); then runs
# the installed `igaprep run` (no case: the built-in ring2) from a folder
# outside the source tree and checks the model's /provenance.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${WORK_DIR}/build
                -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer project failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer project failed (${rc})")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "consumer ok 1 1 2")
  message(FATAL_ERROR "consumer program failed: rc=${rc} output='${out}'")
endif()
message(STATUS "consumer: ${out}")

# The installed program must not know where the source tree is.
file(READ ${WORK_DIR}/prefix/bin/igaprep binary HEX)
string(HEX "${SOURCE_DIR}" source_hex)
string(FIND "${binary}" "${source_hex}" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the installed igaprep names the source tree ${SOURCE_DIR}")
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/elsewhere)
execute_process(COMMAND ${WORK_DIR}/prefix/bin/igaprep run WORKING_DIRECTORY ${WORK_DIR}/elsewhere
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/elsewhere/output/model.h5)
  message(FATAL_ERROR "installed igaprep run: rc=${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND /usr/bin/python3 -c "import h5py, json; p = h5py.File('output/model.h5', 'r')['provenance'].attrs; \
i = json.loads(p['inputs']); c = json.loads(p['case']); \
assert p['generator'].startswith('igaprep 0.'), p['generator']; assert c['name'] == 'ring2', c; \
assert i['options']['fit']['degree'] == 3; assert len(i['date']) == 20; print('provenance ok', p['generator'])"
                WORKING_DIRECTORY ${WORK_DIR}/elsewhere RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "provenance of the installed run's model: ${out}${err}")
endif()
message(STATUS "${out}")

# A consumer of the export and spline components alone, configured with
# every other dependency hidden (cmake/igaprepConfig.cmake.in).
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/export_only -B ${WORK_DIR}/build_export
                -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON -DCMAKE_DISABLE_FIND_PACKAGE_Ceres=ON
                -DCMAKE_DISABLE_FIND_PACKAGE_OpenSSL=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the export-only consumer failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build_export RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the export-only consumer failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/build_export/export_consumer ${WORK_DIR}/elsewhere/output/model.h5
                ${WORK_DIR}/elsewhere/consumer.vtu RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "export consumer ok 128 0" OR NOT EXISTS ${WORK_DIR}/elsewhere/consumer.vtu)
  message(FATAL_ERROR "export-only consumer: rc=${rc} output='${out}${err}'")
endif()
message(STATUS "${out}")

# The installed Python module, from outside the build tree.
file(GLOB python_dirs ${WORK_DIR}/prefix/lib/python3*/dist-packages)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${python_dirs} /usr/bin/python3 -c
  "import igaprep, json; c = json.load(open('${SOURCE_DIR}/models/sphere2/case.json')); c['validation'] = {'enabled': False}; \
m, r = igaprep.run(c, folder='${SOURCE_DIR}/models/sphere2', write_outputs=False); \
assert igaprep.__file__.startswith('${WORK_DIR}/prefix'), igaprep.__file__; print('python ok', r['check']['passed'], len(m.patches))"
  WORKING_DIRECTORY ${WORK_DIR}/elsewhere RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "python ok True 26")
  message(FATAL_ERROR "installed Python module: ${out}${err}")
endif()
message(STATUS "${out}")
