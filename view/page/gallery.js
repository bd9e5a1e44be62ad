// A gallery page's loader: pages opened from disk (file://) may not fetch files or load
// ES modules from it, so the site carries three.js and the view as strings
// (assets/modules.js: window.knitcModules, address -> source) and its fabric as a script
// (window.knitcStatic). Each module is made a blob URL, its imports pointed at the blob
// URLs of the modules before it, and the view imported last.
(function () {
  const sources = window.knitcModules;
  const order = Object.keys(sources);  // dependencies first, the view last
  const urls = {};
  const resolve = (from, spec) => {
    if (spec === 'three') return '/three/three.module.js';
    if (spec.startsWith('three/addons/')) return '/three/addons/' + spec.slice('three/addons/'.length);
    return new URL(spec, 'http://site' + from).pathname;
  };
  for (const address of order) {
    const code = sources[address].replace(/(\bfrom\s*|\bimport\s*)(['"])([^'"]+)\2/g, (whole, before, quote, spec) => {
      const target = urls[resolve(address, spec)];
      return target ? before + quote + target + quote : whole;
    });
    urls[address] = URL.createObjectURL(new Blob([code], { type: 'text/javascript' }));
  }
  import(urls['/view.js']).catch((e) => {
    const box = document.getElementById('error');
    box.textContent = 'knitc gallery: ' + e;
    box.style.display = 'block';
  });
})();
