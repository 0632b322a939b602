// node check.mjs DIR NAME...: runs each DIR/NAME_threejs.js (written by ltc_export) in Node, with
// DIR/node_modules/three as the stub beside this file, and compares the textures its init()
// builds with the same table's raw float32 files (DIR/NAME_ltc_1.f32, _2.f32) and float16 DDS
// files (DIR/NAME_ltc_1_f16.dds, _2_f16.dds, data after the 148-byte DX10 header): the same
// texels, bit for bit, in the layout three.js uploads (RGBA, width x height, row by row).
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const [ dir, ...names ] = process.argv.slice( 2 );
let failures = 0;
const fail = ( message ) => { console.error( 'FAIL: ' + message ); failures ++; };

function sameBytes( what, got, want ) {
	if ( got.length !== want.length ) return fail( `${what}: ${got.length} bytes, want ${want.length}` );
	if ( Buffer.compare( got, want ) !== 0 ) fail( `${what}: the texels differ` );
}

for ( const name of names ) {
	const { RectAreaLightTexturesLib } = await import( pathToFileURL( join( dir, name + '_threejs.js' ) ).href );
	const before = failures;
	const lib = RectAreaLightTexturesLib.init();
	if ( lib !== RectAreaLightTexturesLib ) fail( `${name}: init() does not return the library` );
	for ( const k of [ 1, 2 ] ) {
		const f32 = readFileSync( join( dir, `${name}_ltc_${k}.f32` ) );
		const dds = readFileSync( join( dir, `${name}_ltc_${k}_f16.dds` ) );
		const width = dds.readUInt32LE( 16 ), height = dds.readUInt32LE( 12 );
		for ( const [ key, type, want ] of [
			[ `LTC_FLOAT_${k}`, 'FloatType', f32 ],
			[ `LTC_HALF_${k}`, 'HalfFloatType', dds.subarray( 148 ) ] ] ) {
			const t = lib[ key ];
			if ( t.image.width !== width || t.image.height !== height ) fail( `${name} ${key}: size` );
			if ( t.format !== 'RGBAFormat' || t.type !== type || ! t.needsUpdate ) fail( `${name} ${key}: format` );
			if ( t.magFilter !== 'LinearFilter' || t.minFilter !== 'NearestFilter' ) fail( `${name} ${key}: filters` );
			const d = t.image.data;
			sameBytes( `${name} ${key}`, Buffer.from( d.buffer, d.byteOffset, d.byteLength ), want );
		}
	}
	if ( failures === before ) console.log( `${name}_threejs.js: the float and half textures are the raw and DDS files' texels` );
}
process.exit( failures ? 1 : 0 );
