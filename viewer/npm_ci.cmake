# Runs `npm ci` in WORK (where package.json and package-lock.json were copied) with NPM, and
# says plainly what went wrong when it fails — most often that the npm registry cannot be
# reached. Packages already in npm's cache (~/.npm) are taken from it, so a machine that has
# built once builds again without the network.
execute_process(COMMAND ${NPM} ci --prefer-offline --no-audit --no-fund --loglevel=error
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR
    "viewer: `npm ci` failed (exit status ${status}). report.html's 3D viewer is bundled at build "
    "time from three.js and esbuild, which npm fetches from the npm registry (versions pinned by "
    "viewer/package-lock.json): the first build needs the registry, later ones find them in npm's "
    "cache (~/.npm). Check the connection or the proxy (npm config get registry), then build again.")
endif()
file(TOUCH ${WORK}/npm-ci.stamp)
