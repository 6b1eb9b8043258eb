// Lamella's strip viewer: a small WebGL viewer of the scene in the page's data block (surface,
// level curves, rectifying strips and their rulings, the flat strips beside them). Written for
// Lamella; it loads nothing from elsewhere.
"use strict";
(function () {
  var selfCheck = document.querySelector("pre[data-self-check]");
  var errors = [];
  var check = { webgl: false, context: null, strips_expected: 0, strips_drawn: 0, strips_seen: 0, colours: [], colouring: null, legend: "", info: "", errors: errors };
  function writeCheck() {
    selfCheck.textContent = JSON.stringify(check);
    selfCheck.setAttribute("data-status", errors.length === 0 && check.webgl ? "ok" : "failed");
  }
  window.addEventListener("error", function (event) { errors.push(String(event.message || event)); writeCheck(); });
  window.addEventListener("unhandledrejection", function (event) { errors.push(String(event.reason)); writeCheck(); });
  var consoleError = console.error;
  console.error = function () {
    errors.push(Array.prototype.map.call(arguments, String).join(" "));
    writeCheck();
    consoleError.apply(console, arguments);
  };

  var data = JSON.parse(document.getElementById("lamella-data").textContent);
  var strips = data.strips;
  check.strips_expected = strips.length;
  writeCheck();

  // ---- decoding: quantised coordinates (16-bit steps of a box, little-endian, base64)
  function bytesOf(text) {
    var binary = atob(text), bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    return new DataView(bytes.buffer);
  }
  // Coordinates relative to `origin`, as floats.
  function dequantise(text, low, high, origin) {
    var view = bytesOf(text), dims = low.length, count = view.byteLength / 2, out = new Float32Array(count);
    for (var i = 0; i < count; i++) {
      var k = i % dims;
      out[i] = low[k] + view.getUint16(2 * i, true) / 65535 * (high[k] - low[k]) - origin[k];
    }
    return out;
  }
  var low = data.box.low, high = data.box.high;
  var centre = [0, 1, 2].map(function (k) { return (low[k] + high[k]) / 2; });
  var radius = Math.max(1e-9, Math.hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]) / 2);

  // ---- colours
  function hsv(h, s, v) {
    var i = Math.floor(h * 6), f = h * 6 - i, p = v * (1 - s), q = v * (1 - f * s), t = v * (1 - (1 - f) * s);
    return [[v, t, p], [q, v, p], [p, v, t], [p, q, v], [t, p, v], [v, p, q]][i % 6];
  }
  function stripColour(i) { return hsv((i * 0.618033988749895) % 1, 0.7, 0.92); }
  var familyColours = [[0.88, 0.44, 0.13], [0.13, 0.5, 0.82], [0.3, 0.65, 0.25], [0.6, 0.3, 0.7]];
  // Blue (good) through green and yellow to red (bad), t in [0, 1].
  var rampStops = [[0.19, 0.36, 0.8], [0.2, 0.7, 0.35], [0.95, 0.8, 0.15], [0.85, 0.15, 0.12]];
  function ramp(t) {
    t = Math.min(1, Math.max(0, t)) * (rampStops.length - 1);
    var k = Math.min(rampStops.length - 2, Math.floor(t)), f = t - k;
    return [0, 1, 2].map(function (c) { return rampStops[k][c] * (1 - f) + rampStops[k + 1][c] * f; });
  }
  function css(rgb) {
    return "#" + rgb.map(function (c) { return ("0" + Math.round(c * 255).toString(16)).slice(-2); }).join("");
  }
  function maxOf(values) { return values.reduce(function (m, v) { return v > m ? v : m; }, 0); }
  var angleScale = Math.max(0.5, maxOf(strips.map(function (s) { return s.metrics.max_quad_angle_error_degrees || 0; })));
  var utilisationScale = Math.max(1, maxOf(strips.map(function (s) { return s.utilisation || 0; })));
  var colourings = [{ key: "strip", label: "strip" }];
  if (data.families.length > 1) colourings.push({ key: "family", label: "family" });
  colourings.push({ key: "angle", label: "angle error of the strip planes" });
  if (data.has_utilisation) colourings.push({ key: "utilisation", label: "bending utilisation" });
  function colourOf(i, key) {
    var s = strips[i];
    if (key === "family") return familyColours[s.family % familyColours.length];
    if (key === "angle") return ramp((s.metrics.max_quad_angle_error_degrees || 0) / angleScale);
    if (key === "utilisation") return s.utilisation === null ? [0.6, 0.6, 0.6] : ramp(s.utilisation / utilisationScale);
    return stripColour(i);
  }
  check.colours = strips.slice(0, 64).map(function (s, i) { return css(stripColour(i)); });

  // ---- WebGL
  var canvas = document.getElementById("view");
  var attributes = { antialias: true, preserveDrawingBuffer: true };
  var gl = canvas.getContext("webgl2", attributes);
  check.context = gl ? "webgl2" : null;
  if (!gl) {
    gl = canvas.getContext("webgl", attributes);
    check.context = gl ? "webgl" : null;
  }
  if (!gl || (check.context === "webgl" && !gl.getExtension("OES_element_index_uint"))) {
    var failure = document.getElementById("failure");
    failure.hidden = false;
    failure.textContent = "This browser cannot draw the design: WebGL (with 32-bit indices) is not available.";
    errors.push("no WebGL context with 32-bit indices");
    writeCheck();
    return;
  }
  check.webgl = true;

  function shader(type, source) {
    var s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error("shader: " + gl.getShaderInfoLog(s));
    return s;
  }
  var program = gl.createProgram();
  gl.attachShader(program, shader(gl.VERTEX_SHADER, [
    "attribute vec3 position; attribute vec3 normal; attribute vec3 colour;",
    "uniform mat4 matrix; uniform vec3 light; uniform float lit;",
    "varying vec3 shade;",
    "void main() {",
    "  gl_Position = matrix * vec4(position, 1.0);",
    "  float facing = abs(dot(normalize(normal), light));",
    "  shade = mix(colour, colour * (0.45 + 0.55 * facing), lit);",
    "}"].join("\n")));
  gl.attachShader(program, shader(gl.FRAGMENT_SHADER, "precision mediump float; varying vec3 shade; void main() { gl_FragColor = vec4(shade, 1.0); }"));
  gl.bindAttribLocation(program, 0, "position");
  gl.bindAttribLocation(program, 1, "normal");
  gl.bindAttribLocation(program, 2, "colour");
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error("program: " + gl.getProgramInfoLog(program));
  gl.useProgram(program);
  var uniform = { matrix: gl.getUniformLocation(program, "matrix"), light: gl.getUniformLocation(program, "light"), lit: gl.getUniformLocation(program, "lit") };

  function buffer(array, target) {
    var b = gl.createBuffer();
    gl.bindBuffer(target || gl.ARRAY_BUFFER, b);
    gl.bufferData(target || gl.ARRAY_BUFFER, array, gl.STATIC_DRAW);
    return b;
  }
  // Binds attribute `index` to `b` (three floats a vertex), or holds it at `constant`.
  function attribute(index, b, constant) {
    if (b) {
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.enableVertexAttribArray(index);
      gl.vertexAttribPointer(index, 3, gl.FLOAT, false, 0, 0);
    } else {
      gl.disableVertexAttribArray(index);
      gl.vertexAttrib3f(index, constant[0], constant[1], constant[2]);
    }
  }

  // ---- geometry
  var origin3 = centre;
  var surface = null;
  if (data.surface) {
    var sp = dequantise(data.surface.positions, low, high, origin3);
    var triangles = new Uint32Array(bytesOf(data.surface.triangles).buffer);
    var sn = new Float32Array(sp.length);
    for (var t = 0; t < triangles.length; t += 3) {
      var a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
      var u = [sp[b] - sp[a], sp[b + 1] - sp[a + 1], sp[b + 2] - sp[a + 2]], w = [sp[c] - sp[a], sp[c + 1] - sp[a + 1], sp[c + 2] - sp[a + 2]];
      var n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
      [a, b, c].forEach(function (v) { sn[v] += n[0]; sn[v + 1] += n[1]; sn[v + 2] += n[2]; });
    }
    surface = { positions: buffer(sp), normals: buffer(sn), indices: buffer(triangles, gl.ELEMENT_ARRAY_BUFFER), count: triangles.length };
  }

  var curvePoints = dequantise(data.curves.positions, low, high, origin3), curveSegments = [];
  var start = 0;
  data.curves.counts.forEach(function (count) {
    for (var i = start; i + 1 < start + count; i++) curveSegments.push(curvePoints[3 * i], curvePoints[3 * i + 1], curvePoints[3 * i + 2], curvePoints[3 * i + 3], curvePoints[3 * i + 4], curvePoints[3 * i + 5]);
    start += count;
  });
  var curves = { positions: buffer(new Float32Array(curveSegments)), count: curveSegments.length / 3 };

  // Strips: per ruling i of strip s, its two ends left_i, right_i one after the other.
  var ends3 = dequantise(data.strip_positions, low, high, origin3);
  var flatLow = data.flat.low, flatHigh = data.flat.high;
  var ends2 = dequantise(data.flat.positions, flatLow, flatHigh, [0, 0]);
  var first = [], total = 0;
  strips.forEach(function (s) { first.push(total); total += s.rulings; });
  function point3(r, side) { var k = 3 * (2 * r + side); return [ends3[k], ends3[k + 1], ends3[k + 2]]; }
  function point2(r, side) { var k = 2 * (2 * r + side); return [ends2[k], ends2[k + 1], 0]; }
  function subtract(p, q) { return [p[0] - q[0], p[1] - q[1], p[2] - q[2]]; }
  function cross(p, q) { return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]; }

  // Triangles of the quads (left_j, left_j+1, right_j+1, right_j), flat-shaded, and per strip
  // the first vertex and vertex count; the outline of each strip as line segments.
  function stripMesh(point) {
    var positions = [], normals = [], ranges = [], outline = [], outlineRanges = [];
    strips.forEach(function (s, i) {
      var begin = positions.length / 3, outlineBegin = outline.length / 3;
      for (var j = 0; j + 1 < s.rulings; j++) {
        var r = first[i] + j;
        var l0 = point(r, 0), r0 = point(r, 1), l1 = point(r + 1, 0), r1 = point(r + 1, 1);
        var normal = cross(subtract(l1, l0), subtract(r0, l0));
        [l0, l1, r1, l0, r1, r0].forEach(function (p) { positions.push(p[0], p[1], p[2]); normals.push(normal[0], normal[1], normal[2]); });
        [l0, l1, r0, r1].forEach(function (p) { outline.push(p[0], p[1], p[2]); });
      }
      [[first[i], first[i]], [first[i] + s.rulings - 1, first[i] + s.rulings - 1]].forEach(function (pair) {
        var p = point(pair[0], 0), q = point(pair[1], 1);
        outline.push(p[0], p[1], p[2], q[0], q[1], q[2]);
      });
      ranges.push([begin, positions.length / 3 - begin]);
      outlineRanges.push([outlineBegin, outline.length / 3 - outlineBegin]);
    });
    var pick = [];
    ranges.forEach(function (range, i) {
      var id = i + 1, rgb = [(id & 255) / 255, ((id >> 8) & 255) / 255, ((id >> 16) & 255) / 255];
      for (var v = 0; v < range[1]; v++) pick.push(rgb[0], rgb[1], rgb[2]);
    });
    return {
      positions: buffer(new Float32Array(positions)), normals: buffer(new Float32Array(normals)), pick: buffer(new Float32Array(pick)),
      colours: buffer(new Float32Array(positions.length)), ranges: ranges, count: positions.length / 3,
      outline: buffer(new Float32Array(outline)), outlineRanges: outlineRanges
    };
  }
  var strips3 = stripMesh(point3), strips2 = stripMesh(point2);
  check.strips_drawn = strips3.ranges.filter(function (r, i) { return r[1] > 0 && strips2.ranges[i][1] > 0; }).length;

  var rulingSegments = [];
  for (var r = 0; r < total; r++) {
    var p = point3(r, 0), q = point3(r, 1);
    rulingSegments.push(p[0], p[1], p[2], q[0], q[1], q[2]);
  }
  var rulings = { positions: buffer(new Float32Array(rulingSegments)), count: rulingSegments.length / 3 };

  // ---- state and controls
  var state = { colouring: "strip", surface: true, curves: true, rulings: false, flat: true, hovered: -1, selected: -1 };
  var camera = { yaw: -0.9, pitch: 0.55, distance: 3 * radius, target: [0, 0, 0], fitted: false };
  var flatExtent = [flatHigh[0] - flatLow[0], flatHigh[1] - flatLow[1]];
  var flatCamera = { centre: [(flatLow[0] + flatHigh[0]) / 2, (flatLow[1] + flatHigh[1]) / 2], scale: 0 };

  var select = document.getElementById("colouring");
  colourings.forEach(function (c) {
    var option = document.createElement("option");
    option.value = c.key;
    option.textContent = c.label;
    select.appendChild(option);
  });
  // The page's address may choose the colouring and a selected strip: view.html#colour=angle&strip=3.
  location.hash.replace(/^#/, "").split("&").forEach(function (pair) {
    var parts = pair.split("=");
    if (parts[0] === "colour" && colourings.some(function (c) { return c.key === parts[1]; })) state.colouring = parts[1];
    if (parts[0] === "strip" && /^[0-9]+$/.test(parts[1]) && Number(parts[1]) < strips.length) state.selected = Number(parts[1]);
  });
  select.value = state.colouring;
  select.addEventListener("change", function () { state.colouring = select.value; recolour(); });
  ["surface", "curves", "rulings", "flat"].forEach(function (key) {
    var box = document.getElementById("show-" + key);
    box.checked = state[key];
    box.addEventListener("change", function () { state[key] = box.checked; resize(); });
  });

  function recolour() {
    var colours = [];
    strips3.ranges.forEach(function (range, i) {
      var rgb = colourOf(i, state.colouring);
      for (var v = 0; v < range[1]; v++) colours.push(rgb[0], rgb[1], rgb[2]);
    });
    var array = new Float32Array(colours);
    [strips3, strips2].forEach(function (m) { gl.bindBuffer(gl.ARRAY_BUFFER, m.colours); gl.bufferData(gl.ARRAY_BUFFER, array, gl.STATIC_DRAW); });
    legend();
    render();
  }

  function legend() {
    var box = document.getElementById("legend");
    box.textContent = "";
    function line(text) { var p = document.createElement("div"); p.textContent = text; box.appendChild(p); return p; }
    function rampLegend(title, max, unit, factor) {
      line(title);
      var bar = document.createElement("div");
      bar.className = "ramp";
      bar.style.background = "linear-gradient(to right, " + rampStops.map(css).join(", ") + ")";
      box.appendChild(bar);
      var labels = document.createElement("div");
      labels.className = "ramp-labels";
      [0, max / 2, max].forEach(function (v) { var span = document.createElement("span"); span.textContent = (v * factor).toFixed(2) + " " + unit; labels.appendChild(span); });
      box.appendChild(labels);
    }
    if (state.colouring === "strip") {
      line("Each strip its own colour (" + strips.length + " strips, " + data.families.join(", ") + ").");
    } else if (state.colouring === "family") {
      data.families.forEach(function (name, k) {
        var row = line(" family " + name + " (" + strips.filter(function (s) { return s.family === k; }).length + " strips)");
        var swatch = document.createElement("span");
        swatch.className = "swatch";
        swatch.style.background = css(familyColours[k % familyColours.length]);
        row.insertBefore(swatch, row.firstChild);
      });
    } else if (state.colouring === "angle") {
      rampLegend("Largest angle error of a strip's rectifying planes against θ", angleScale, "°", 1);
    } else {
      rampLegend("Largest bending utilisation (von Mises stress / allowable stress)", utilisationScale, "%", 100);
    }
  }

  // ---- the strip's figures (Table 4)
  var figures = [
    ["length", function (s) { return s.metrics.length; }, "m", 3],
    ["θ error (max diff θ)", function (s) { return s.metrics.max_diff_theta_degrees; }, "°", 3],
    ["strip-plane angle error", function (s) { return s.metrics.max_quad_angle_error_degrees; }, "°", 3],
    ["e_straight (of length)", function (s) { return s.metrics.e_straight; }, "", -2],
    ["E_planar", function (s) { return s.metrics.e_planar; }, "", -2],
    ["max planarity", function (s) { return s.metrics.max_planar; }, "", -2],
    ["Appro (of diagonal)", function (s) { return s.metrics.appro_percent; }, "%", 4],
    ["flipped quads", function (s) { return s.metrics.flipped_quads; }, "", 0],
    ["longest ruling", function (s) { return s.metrics.max_ruling_over_width; }, "widths", 2],
    ["rulings", function (s) { return s.rulings; }, "", 0]
  ];
  if (data.has_utilisation) figures.push(["bending utilisation", function (s) { return s.utilisation === null ? null : 100 * s.utilisation; }, "%", 1]);
  function format(value, digits) {
    if (value === null || value === undefined) return "n/a";
    return digits < 0 ? value.toExponential(-digits) : value.toFixed(digits);
  }
  function showInfo() {
    var i = state.hovered >= 0 ? state.hovered : state.selected, box = document.getElementById("info");
    box.textContent = "";
    if (i < 0) {
      var hint = document.createElement("p");
      hint.className = "hint";
      hint.textContent = "Hover over a strip, or click it to keep its figures here.";
      box.appendChild(hint);
      return;
    }
    var s = strips[i], title = document.createElement("strong");
    title.textContent = s.name + " (id " + i + ", family " + data.families[s.family] + ")" + (i === state.selected ? " · selected" : "");
    box.appendChild(title);
    var table = document.createElement("table");
    figures.forEach(function (f) {
      var row = table.insertRow(), name = row.insertCell(), value = row.insertCell();
      name.textContent = f[0];
      value.className = "value";
      value.textContent = format(f[1](s), f[3]) + (f[2] ? " " + f[2] : "");
    });
    box.appendChild(table);
  }

  // ---- matrices (column-major)
  function multiply(a, b) {
    var m = new Float32Array(16);
    for (var c = 0; c < 4; c++) for (var r = 0; r < 4; r++) m[4 * c + r] = a[r] * b[4 * c] + a[4 + r] * b[4 * c + 1] + a[8 + r] * b[4 * c + 2] + a[12 + r] * b[4 * c + 3];
    return m;
  }
  function normalise(v) { var l = Math.hypot(v[0], v[1], v[2]) || 1; return [v[0] / l, v[1] / l, v[2] / l]; }
  function dot(p, q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
  function eyeDirection() {
    return [Math.cos(camera.pitch) * Math.cos(camera.yaw), Math.cos(camera.pitch) * Math.sin(camera.yaw), Math.sin(camera.pitch)];
  }
  function cameraAxes() {
    var back = eyeDirection(), right = normalise(cross([0, 0, 1], back)), up = cross(back, right);
    return { back: back, right: right, up: up };
  }
  function viewMatrix(aspect) {
    var axes = cameraAxes(), eye = [0, 1, 2].map(function (k) { return camera.target[k] + camera.distance * axes.back[k]; });
    var view = new Float32Array([axes.right[0], axes.up[0], axes.back[0], 0, axes.right[1], axes.up[1], axes.back[1], 0, axes.right[2], axes.up[2], axes.back[2], 0,
      -dot(axes.right, eye), -dot(axes.up, eye), -dot(axes.back, eye), 1]);
    var near = Math.max(camera.distance - 2 * radius, camera.distance * 0.01), far = camera.distance + 2 * radius, f = 1 / Math.tan(0.35);
    var projection = new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, 2 * far * near / (near - far), 0]);
    return multiply(projection, view);
  }
  function flatMatrix(width, height) {
    var s = flatCamera.scale;
    return new Float32Array([2 * s / width, 0, 0, 0, 0, 2 * s / height, 0, 0, 0, 0, 1, 0, -2 * s * flatCamera.centre[0] / width, -2 * s * flatCamera.centre[1] / height, 0, 1]);
  }

  // ---- drawing
  var regions = { three: [0, 0, 1, 1], flat: null };
  function resize() {
    var ratio = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    canvas.height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    var split = state.flat ? Math.round(canvas.width * 0.6) : canvas.width;
    regions.three = [0, 0, split, canvas.height];
    regions.flat = state.flat ? [split, 0, canvas.width - split, canvas.height] : null;
    if (!camera.fitted) {
      // The whole scene in view: its bounding sphere within the narrower field of view.
      var half = Math.atan(Math.tan(0.35) * Math.min(1, split / canvas.height));
      camera.distance = 1.05 * radius / Math.sin(half);
      camera.fitted = true;
    }
    if (regions.flat && flatCamera.scale === 0) {
      flatCamera.scale = 0.9 * Math.min(regions.flat[2] / Math.max(flatExtent[0], 1e-9), regions.flat[3] / Math.max(flatExtent[1], 1e-9));
    }
    render();
  }
  function drawTriangles(m, colours, range) {
    attribute(0, m.positions);
    attribute(1, m.normals);
    attribute(2, colours);
    if (range) gl.drawArrays(gl.TRIANGLES, range[0], range[1]); else gl.drawArrays(gl.TRIANGLES, 0, m.count);
  }
  function drawLines(positions, first, count, colour) {
    attribute(0, positions);
    attribute(1, null, [0, 0, 1]);
    attribute(2, null, colour);
    gl.uniform1f(uniform.lit, 0);
    gl.drawArrays(gl.LINES, first, count);
  }
  function highlight(m) {
    [state.selected, state.hovered].forEach(function (i) {
      if (i >= 0) drawLines(m.outline, m.outlineRanges[i][0], m.outlineRanges[i][1], [0, 0, 0]);
    });
  }
  // Draws both views; with `picking`, strip ids as colours and everything else black.
  function draw(picking) {
    gl.enable(gl.SCISSOR_TEST);
    gl.enable(gl.DEPTH_TEST);
    var r = regions.three;
    gl.viewport(r[0], r[1], r[2], r[3]);
    gl.scissor(r[0], r[1], r[2], r[3]);
    if (picking) gl.clearColor(0, 0, 0, 1); else gl.clearColor(0.957, 0.957, 0.949, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.uniformMatrix4fv(uniform.matrix, false, viewMatrix(r[2] / r[3]));
    gl.uniform3fv(uniform.light, cameraAxes().back);
    gl.uniform1f(uniform.lit, picking ? 0 : 1);
    if (state.surface && surface) {
      gl.enable(gl.POLYGON_OFFSET_FILL);
      gl.polygonOffset(1, 1);
      attribute(0, surface.positions);
      attribute(1, surface.normals);
      attribute(2, null, picking ? [0, 0, 0] : [0.82, 0.82, 0.8]);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, surface.indices);
      gl.drawElements(gl.TRIANGLES, surface.count, gl.UNSIGNED_INT, 0);
      gl.disable(gl.POLYGON_OFFSET_FILL);
    }
    gl.uniform1f(uniform.lit, picking ? 0 : 1);
    drawTriangles(strips3, picking ? strips3.pick : strips3.colours);
    if (!picking) {
      if (state.curves) drawLines(curves.positions, 0, curves.count, [0.1, 0.15, 0.35]);
      if (state.rulings) drawLines(rulings.positions, 0, rulings.count, [0.25, 0.25, 0.25]);
      highlight(strips3);
    }
    if (regions.flat) {
      r = regions.flat;
      gl.viewport(r[0], r[1], r[2], r[3]);
      gl.scissor(r[0], r[1], r[2], r[3]);
      if (picking) gl.clearColor(0, 0, 0, 1); else gl.clearColor(1, 1, 1, 1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      gl.disable(gl.DEPTH_TEST);
      gl.uniformMatrix4fv(uniform.matrix, false, flatMatrix(r[2], r[3]));
      gl.uniform1f(uniform.lit, 0);
      drawTriangles(strips2, picking ? strips2.pick : strips2.colours);
      if (!picking) highlight(strips2);
    }
    gl.disable(gl.SCISSOR_TEST);
  }
  var pickTarget = null;
  // Renders the ids into an offscreen framebuffer and returns its pixels in `rect` (x, y, w, h).
  function pickPixels(rect) {
    if (!pickTarget || pickTarget.width !== canvas.width || pickTarget.height !== canvas.height) {
      pickTarget = { width: canvas.width, height: canvas.height, framebuffer: gl.createFramebuffer(), texture: gl.createTexture(), depth: gl.createRenderbuffer() };
      gl.bindTexture(gl.TEXTURE_2D, pickTarget.texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, canvas.width, canvas.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.bindRenderbuffer(gl.RENDERBUFFER, pickTarget.depth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT16, canvas.width, canvas.height);
      gl.bindFramebuffer(gl.FRAMEBUFFER, pickTarget.framebuffer);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, pickTarget.texture, 0);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, pickTarget.depth);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, pickTarget.framebuffer);
    draw(true);
    var pixels = new Uint8Array(4 * rect[2] * rect[3]);
    gl.readPixels(rect[0], rect[1], rect[2], rect[3], gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return pixels;
  }
  function idAt(pixels, k) { return (pixels[k] | (pixels[k + 1] << 8) | (pixels[k + 2] << 16)) - 1; }
  var pending = false;
  function render() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () { pending = false; draw(false); showInfo(); });
  }

  // ---- mouse
  function canvasPoint(event) {
    var box = canvas.getBoundingClientRect(), ratio = canvas.width / Math.max(1, box.width);
    return [(event.clientX - box.left) * ratio, (box.bottom - event.clientY) * ratio];
  }
  function regionAt(p) { return regions.flat && p[0] >= regions.flat[0] ? "flat" : "three"; }
  function stripAt(p) {
    var x = Math.floor(p[0]), y = Math.floor(p[1]);
    if (x < 0 || y < 0 || x >= canvas.width || y >= canvas.height) return -1;
    return idAt(pickPixels([x, y, 1, 1]), 0);
  }
  var drag = null;
  canvas.addEventListener("contextmenu", function (event) { event.preventDefault(); });
  canvas.addEventListener("mousedown", function (event) {
    var p = canvasPoint(event);
    drag = { region: regionAt(p), last: p, start: p, pan: event.button === 2 || event.shiftKey };
  });
  window.addEventListener("mouseup", function (event) {
    if (drag && Math.hypot(drag.last[0] - drag.start[0], drag.last[1] - drag.start[1]) < 3 && event.target === canvas) {
      var i = stripAt(canvasPoint(event));
      state.selected = i === state.selected ? -1 : i;
      render();
    }
    drag = null;
  });
  window.addEventListener("mousemove", function (event) {
    var p = canvasPoint(event);
    if (!drag) {
      if (event.target === canvas) {
        var i = stripAt(p);
        if (i !== state.hovered) { state.hovered = i; render(); }
      }
      return;
    }
    var dx = p[0] - drag.last[0], dy = p[1] - drag.last[1];
    drag.last = p;
    if (drag.region === "flat") {
      flatCamera.centre[0] -= dx / flatCamera.scale;
      flatCamera.centre[1] -= dy / flatCamera.scale;
    } else if (drag.pan) {
      var axes = cameraAxes(), step = camera.distance * 0.7 / regions.three[3] * 2;
      for (var k = 0; k < 3; k++) camera.target[k] -= (axes.right[k] * dx + axes.up[k] * dy) * step;
    } else {
      camera.yaw -= dx * 0.008;
      camera.pitch = Math.max(-1.55, Math.min(1.55, camera.pitch - dy * 0.008));
    }
    render();
  });
  canvas.addEventListener("mouseleave", function () { if (state.hovered >= 0) { state.hovered = -1; render(); } });
  canvas.addEventListener("wheel", function (event) {
    event.preventDefault();
    var factor = Math.exp(event.deltaY * 0.001);
    if (regionAt(canvasPoint(event)) === "flat") flatCamera.scale /= factor;
    else camera.distance = Math.min(50 * radius, Math.max(0.05 * radius, camera.distance * factor));
    render();
  }, { passive: false });
  window.addEventListener("resize", resize);

  // ---- first frame and the self-check
  recolour();
  resize();
  draw(false);
  var r3 = regions.three, pixels = pickPixels(r3), seen = {};
  for (var k = 0; k < pixels.length; k += 4) { var id = idAt(pixels, k); if (id >= 0 && id < strips.length) seen[id] = true; }
  check.strips_seen = Object.keys(seen).length;
  draw(false);
  showInfo();
  check.colouring = state.colouring;
  check.legend = document.getElementById("legend").textContent;
  check.info = document.getElementById("info").textContent;
  writeCheck();
})();
