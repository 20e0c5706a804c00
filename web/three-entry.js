// What the replay page (replay.js) takes from three.js: the whole of three, the glTF loader and
// the orbit controls, as one classic script that sets the global TumbleThree (npm run bundle). A
// page opened from file:// cannot import ES modules by URL (its origin is null), so the replay
// inlines this one script.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export { THREE, GLTFLoader, OrbitControls };
