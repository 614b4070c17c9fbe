// A local stand-in for the relay during development (index.html?fixture):
// a hello with a plausible skeleton and a synthetic 20 Hz stream of frames
// in the page's canonical shape, so the scene can be built and checked
// without a server. Not used against a real relay.

const box = (size, center) => ({ shape: 'box', size, center });
export const FIXTURE_SKELETON = {
  name: 'fixture-biped',
  joints: [
    { name: 'pelvis', parent: -1, offset_ls: [0, 0, 0], dofs: 'zxy', segment: box([0.2, 0.16, 0.32], [0, 0, 0]) },
    { name: 'chest', parent: 0, offset_ls: [0, 0.08, 0], dofs: 'zxy', segment: box([0.22, 0.44, 0.38], [0, 0.24, 0]) },
    { name: 'head', parent: 1, offset_ls: [0, 0.5, 0], dofs: 'zy', segment: { shape: 'sphere', size: [0.115, 0, 0], center: [0, 0.12, 0] } },
    { name: 'l_shoulder', parent: 1, offset_ls: [0, 0.42, -0.23], dofs: 'zx', segment: box([0.1, 0.3, 0.1], [0, -0.15, 0]) },
    { name: 'l_elbow', parent: 3, offset_ls: [0, -0.3, 0], dofs: 'z', segment: box([0.08, 0.28, 0.08], [0, -0.14, 0]) },
    { name: 'r_shoulder', parent: 1, offset_ls: [0, 0.42, 0.23], dofs: 'zx', segment: box([0.1, 0.3, 0.1], [0, -0.15, 0]) },
    { name: 'r_elbow', parent: 5, offset_ls: [0, -0.3, 0], dofs: 'z', segment: box([0.08, 0.28, 0.08], [0, -0.14, 0]) },
    { name: 'l_hip', parent: 0, offset_ls: [0, -0.06, -0.1], dofs: 'zx', segment: box([0.15, 0.44, 0.15], [0, -0.22, 0]) },
    { name: 'l_knee', parent: 7, offset_ls: [0, -0.44, 0], dofs: 'z', segment: box([0.12, 0.42, 0.12], [0, -0.21, 0]) },
    { name: 'l_ankle', parent: 8, offset_ls: [0, -0.44, 0], dofs: 'z', segment: box([0.25, 0.07, 0.1], [0.06, -0.035, 0]) },
    { name: 'r_hip', parent: 0, offset_ls: [0, -0.06, 0.1], dofs: 'zx', segment: box([0.15, 0.44, 0.15], [0, -0.22, 0]) },
    { name: 'r_knee', parent: 10, offset_ls: [0, -0.44, 0], dofs: 'z', segment: box([0.12, 0.42, 0.12], [0, -0.21, 0]) },
    { name: 'r_ankle', parent: 11, offset_ls: [0, -0.44, 0], dofs: 'z', segment: box([0.25, 0.07, 0.1], [0.06, -0.035, 0]) },
  ],
};

export const FIXTURE_HELLO = {
  type: 'hello', protocol_major: 1, protocol_minor: 0, frame_rate: 20,
  skeleton: FIXTURE_SKELETON,
  left: { name: 'FIXTURE_A', color: '#f2c500' },
  right: { name: 'FIXTURE_B', color: '#d62828' },
  field: {}, server_params: {},
};

const FORMATION = [[-49, 0], [-38, -20], [-40, -7], [-40, 7], [-38, 20], [-22, -22],
  [-24, -6], [-24, 6], [-22, 22], [-8, -8], [-8, 8]];

// Frame `seq` of the synthetic game.
export function fixtureFrame(seq) {
  const t = seq / 20;
  const bx = 30 * Math.sin(t * 0.2), by = 15 * Math.sin(t * 0.13);
  const players = [];
  for (const side of [1, -1]) {
    FORMATION.forEach(([fx, fy], i) => {
      const unum = i + 1;
      const ph = unum * 0.7 + (side < 0 ? 2 : 0);
      const x = side * fx + 6 * Math.sin(t * 0.3 + ph) + bx * 0.3;
      const y = fy + 4 * Math.cos(t * 0.25 + ph) + by * 0.3;
      // Heading: the direction of motion (derivative of the path).
      const vx = 1.8 * Math.cos(t * 0.3 + ph) + 0.09 * 30 * Math.cos(t * 0.2) * 0.2;
      const vy = -1.0 * Math.sin(t * 0.25 + ph) + 0.3 * 15 * 0.13 * Math.cos(t * 0.13);
      const heading = Math.atan2(vy, vx) * 180 / Math.PI;
      const g = Math.sin(t * 9 + ph);            // gait phase
      const swing = 35 * g;
      const angles = [
        0, 0, 0,                       // pelvis zxy
        -8, 0, 0,                      // chest: lean forward
        0, 0,                          // head zy
        -swing * 0.8, 8,               // l_shoulder
        50,                            // l_elbow
        swing * 0.8, -8,               // r_shoulder
        50,                            // r_elbow
        swing, 0,                      // l_hip
        -30 - 30 * Math.max(0, -g),    // l_knee
        5,                             // l_ankle
        -swing, 0,                     // r_hip
        -30 - 30 * Math.max(0, g),     // r_knee
        5,                             // r_ankle
      ];
      const kick = (seq % 60 === 0 && unum === (Math.floor(seq / 60) % 11) + 1 && side === 1) ? 0x2 : 0;
      players.push({ side, unum, state: 0x1 | (unum === 1 ? 0x8 : 0) | kick,
        x, y, z: 0.94, heading, angles: Float32Array.from(angles), stamina: 8000 - (seq % 4000) });
    });
  }
  return {
    seq, time: Math.floor(seq / 2), stoppage: 0, substep: seq % 2, serverTimeMs: Date.now(),
    playMode: 3, scoreLeft: 1, scoreRight: 0,
    ball: { x: bx, y: by, z: Math.max(0, 2 * Math.sin(t * 1.3)) },
    players, extras: null,
  };
}

// Drives the page like a relay would: hello, then a frame every 50 ms.
export function startFixture({ onHello, onFrame }) {
  onHello(FIXTURE_HELLO);
  let seq = 1000;
  return setInterval(() => onFrame(fixtureFrame(seq++)), 50);
}
