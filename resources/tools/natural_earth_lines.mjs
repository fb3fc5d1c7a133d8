// Converts Natural Earth coastlines and country borders, as TopoJSON in npm's world-atlas
// package, into resources/map/natural_earth_lines.bin: the compact file ensil embeds (read by
// geo/natural_earth.cpp). Run once, by hand, when the source changes:
//
//   cd "$(mktemp -d)" && npm install --no-save world-atlas@2.0.2 topojson-client@3.1.0
//   node <repo>/resources/tools/natural_earth_lines.mjs node_modules <repo>/resources/map
//
// topojson-client's mesh() turns the shared arcs into lines: the land's outline is the
// coastline, arcs between two different countries are borders. Natural Earth cuts polygons at
// the antimeridian and closes Antarctica along the south pole; those cuts are not coast and are
// dropped here so no false line runs along 180 degrees or the map's bottom edge.
//
// File layout (little-endian): "ENSILNE1", uint32 layer count; per layer: uint8 feature
// (0 coastlines, 1 borders), uint8 scale (110 or 50: Natural Earth 1:110m or 1:50m), uint16 0,
// uint32 line count; per line: uint32 point count, then per point int16 longitude and int16
// latitude in units of 180/32767 degrees (0.0055 degrees, about 600 m: finer than 1:50m).
import { createRequire } from "node:module";
import { writeFileSync } from "node:fs";
import path from "node:path";

const [modules, outDir] = process.argv.slice(2);
if (!modules || !outDir) {
    console.error("usage: node natural_earth_lines.mjs NODE_MODULES_DIR OUTPUT_DIR");
    process.exit(2);
}
const require = createRequire(path.resolve(modules) + "/");
const topojson = require("topojson-client");

const kUnit = 180 / 32767;
const isCut = (a, b) =>
    (Math.abs(a[0]) > 179.99 && Math.abs(b[0]) > 179.99) || (a[1] < -89.99 && b[1] < -89.99);

// Splits lines where a segment is an antimeridian or pole cut; drops what is left shorter
// than a segment.
function withoutCuts(lines) {
    const out = [];
    for (const line of lines) {
        let current = [line[0]];
        for (let i = 1; i < line.length; ++i) {
            if (isCut(line[i - 1], line[i])) {
                if (current.length > 1) out.push(current);
                current = [line[i]];
            } else {
                current.push(line[i]);
            }
        }
        if (current.length > 1) out.push(current);
    }
    return out;
}

const layers = [];
for (const scale of [110, 50]) {
    const topo = require(`world-atlas/countries-${scale}m.json`);
    const coast = topojson.mesh(topo, topo.objects.land).coordinates;
    const borders = topojson.mesh(topo, topo.objects.countries, (a, b) => a !== b).coordinates;
    layers.push({ feature: 0, scale, lines: withoutCuts(coast) });
    layers.push({ feature: 1, scale, lines: borders });
}

const parts = [Buffer.from("ENSILNE1", "latin1")];
const u32 = (v) => { const b = Buffer.alloc(4); b.writeUInt32LE(v); return b; };
parts.push(u32(layers.length));
for (const layer of layers) {
    const head = Buffer.alloc(8);
    head.writeUInt8(layer.feature, 0);
    head.writeUInt8(layer.scale, 1);
    head.writeUInt16LE(0, 2);
    head.writeUInt32LE(layer.lines.length, 4);
    parts.push(head);
    let points = 0;
    for (const line of layer.lines) {
        parts.push(u32(line.length));
        const b = Buffer.alloc(4 * line.length);
        line.forEach(([lon, lat], i) => {
            b.writeInt16LE(Math.round(lon / kUnit), 4 * i);
            b.writeInt16LE(Math.round(lat / kUnit), 4 * i + 2);
        });
        parts.push(b);
        points += line.length;
    }
    console.log(`1:${layer.scale}m ${layer.feature ? "borders" : "coastlines"}: ` +
                `${layer.lines.length} lines, ${points} points`);
}
const file = path.join(outDir, "natural_earth_lines.bin");
writeFileSync(file, Buffer.concat(parts));
console.log(`wrote ${file}`);
