# The peers of the comparative study (libccd, FCL, Bullet, Box2D) and Google Benchmark,
# from Debian's packages (cmake/install-deps.sh). Everything builds without any of them
# and says which it left out. Each found peer adds a definition GJKX_HAVE_<PEER> to the
# interface target gjkx_study_peers, which the library gjkx::study links.
add_library(gjkx_study_peers INTERFACE)
set(gjkx_peers_found "")
set(gjkx_peers_missing "")

# gjkx_peer(<name> <found?> <target> <DEFINE>): links <target> and defines <DEFINE>=1 when found.
macro(gjkx_peer name isFound target define)
  if(${isFound})
    target_link_libraries(gjkx_study_peers INTERFACE ${target})
    target_compile_definitions(gjkx_study_peers INTERFACE ${define}=1)
    list(APPEND gjkx_peers_found ${name})
  else()
    list(APPEND gjkx_peers_missing ${name})
  endif()
endmacro()

find_package(PkgConfig)
if(PkgConfig_FOUND)
  pkg_check_modules(CCD IMPORTED_TARGET ccd)          # libccd: GJK, MPR
  pkg_check_modules(BULLET IMPORTED_TARGET bullet)    # Bullet (single precision build)
endif()
find_package(fcl QUIET)
find_package(box2d QUIET)
gjkx_peer(libccd CCD_FOUND PkgConfig::CCD GJKX_HAVE_CCD)
gjkx_peer(Bullet BULLET_FOUND PkgConfig::BULLET GJKX_HAVE_BULLET)
gjkx_peer(FCL fcl_FOUND fcl GJKX_HAVE_FCL)
gjkx_peer(Box2D box2d_FOUND box2d::box2d GJKX_HAVE_BOX2D)

find_package(benchmark QUIET)
set(GJKX_HAVE_BENCHMARK ${benchmark_FOUND})
if(benchmark_FOUND)
  list(APPEND gjkx_peers_found "Google Benchmark")
else()
  list(APPEND gjkx_peers_missing "Google Benchmark")
endif()

list(JOIN gjkx_peers_found ", " foundText)
message(STATUS "gjkx study: peers found: ${foundText}")
if(gjkx_peers_missing)
  list(JOIN gjkx_peers_missing ", " missingText)
  message(STATUS "gjkx study: peers left out (not installed): ${missingText}")
endif()
