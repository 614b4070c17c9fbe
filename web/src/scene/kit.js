// Team kits: colours from the hello (or defaults), one set of materials per
// team and role, and canvas textures for shirt numbers.
import * as THREE from 'three';

export const DEFAULT_TEAMS = Object.freeze({
  left: { name: 'Left', color: '#f2c500', goalie: '#7d3cb5', number: '#111111' },
  right: { name: 'Right', color: '#d62828', goalie: '#16a6b6', number: '#ffffff' },
});

// '#rgb', '#rrggbb', 0xRRGGBB or [r,g,b] (0..255 or 0..1) -> THREE.Color
export function toColor(v, fallback) {
  try {
    if (Array.isArray(v) && v.length >= 3) {
      const k = v.some((x) => x > 1) ? 1 / 255 : 1;
      return new THREE.Color().setRGB(v[0] * k, v[1] * k, v[2] * k, THREE.SRGBColorSpace);
    }
    if (typeof v === 'number' || (typeof v === 'string' && /^#?[0-9a-f]{3,6}$/i.test(v)))
      return new THREE.Color(typeof v === 'string' && v[0] !== '#' ? `#${v}` : v);
  } catch { /* fall through */ }
  return new THREE.Color(fallback);
}

// Readable number colour on a shirt: dark on light shirts, white on dark ones.
export function contrastColor(c) {
  const l = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  return l > 0.45 ? new THREE.Color('#111111') : new THREE.Color('#ffffff');
}

// side: 'left' | 'right'; team: hello entry (name, color, goalie colour...).
export function makeKit(side, team = {}) {
  const d = DEFAULT_TEAMS[side];
  const shirt = toColor(team.color ?? team.colour ?? team.shirt, d.color);
  const goalie = toColor(team.goalie_color ?? team.goalieColor ?? team.goalie, d.goalie);
  const shorts = team.shorts ? toColor(team.shorts, '#ffffff') : shirt.clone().multiplyScalar(0.35);
  const std = (color, roughness = 0.7) => new THREE.MeshStandardMaterial({ color, roughness });
  const common = {
    skin: std(0xc99a74, 0.8), boot: std(0x161616, 0.5), shorts: std(shorts),
  };
  return {
    name: team.name || d.name,
    shirtColor: shirt,
    goalieColor: goalie,
    field: { ...common, shirt: std(shirt), sock: std(shirt) },
    goalie: { ...common, shirt: std(goalie), sock: std(goalie), shorts: std(goalie.clone().multiplyScalar(0.4)) },
  };
}

const numberCache = new Map();
// A square canvas texture with the number, transparent around it.
export function numberTexture(n, color, outline) {
  const key = `${n}|${color.getHexString()}|${outline ?? ''}`;
  if (numberCache.has(key)) return numberCache.get(key);
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d');
  g.font = 'bold 92px system-ui, "DejaVu Sans", sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  if (outline) {
    g.lineWidth = 12;
    g.strokeStyle = outline;
    g.strokeText(String(n), 64, 70);
  }
  g.fillStyle = `#${color.getHexString()}`;
  g.fillText(String(n), 64, 70);
  const tex = new THREE.CanvasTexture(c);
  tex.colorSpace = THREE.SRGBColorSpace;
  tex.anisotropy = 4;
  numberCache.set(key, tex);
  return tex;
}
