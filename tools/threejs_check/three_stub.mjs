// The few names of three.js that an exported module (ltc_export --formats threejs) imports, as
// plain values: enough to run its init() in Node and look at the textures it builds.
export const ClampToEdgeWrapping = 'ClampToEdgeWrapping';
export const FloatType = 'FloatType';
export const HalfFloatType = 'HalfFloatType';
export const LinearFilter = 'LinearFilter';
export const NearestFilter = 'NearestFilter';
export const RGBAFormat = 'RGBAFormat';
export const UVMapping = 'UVMapping';

export class DataTexture {
	constructor( data, width, height, format, type, mapping, wrapS, wrapT, magFilter, minFilter, anisotropy ) {
		this.image = { data, width, height };
		Object.assign( this, { format, type, mapping, wrapS, wrapT, magFilter, minFilter, anisotropy } );
		this.needsUpdate = false;
	}
}
