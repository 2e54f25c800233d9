// Linked before a wasm32 program's own JavaScript (cmake/emscripten.cmake, --pre-js): the program sees node's
// environment through getenv, as a native program sees its own (RICOCHET_KERNEL, RICOCHET_FUZZ_SCENE_OUT, NO_COLOR…).
// Emscripten gives a program a fixed, browser-like environment instead; entries of its ENV object, set before the
// program starts, replace those.
Module['preRun'] = Module['preRun'] || [];
Module['preRun'].push(function () {
  for (var name in process.env) ENV[name] = process.env[name];
});
