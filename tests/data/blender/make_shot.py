# Makes the Blender-exported camera files the path-import tests read: a camera
# keyed at frames 1, 25 and 49 (Bezier), exported by Blender's own glTF exporter
# sampled (LINEAR, a key a frame) and unsampled (CUBICSPLINE), and the camera's
# world matrix as Blender evaluates it at every frame, in glTF's Y-up frame
# (blender-shot.json; rounded to 7 places afterwards).
#   cd tests/data/blender && blender -b --python make_shot.py     (Debian 12: blender, python3-numpy)
import numpy
numpy.bool = bool
import bpy, math, json, os, mathutils
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 24
scene.frame_start, scene.frame_end = 1, 49
cd = bpy.data.cameras.new('ShotCam'); cd.sensor_fit = 'VERTICAL'; cd.angle = math.radians(50); cd.clip_start = 0.1; cd.clip_end = 500
cam = bpy.data.objects.new('ShotCam', cd); scene.collection.objects.link(cam)
keys = [(1, (30, -40, 25), (60, 0, 20)), (25, (10, -20, 15), (70, 0, 60)), (49, (-20, -10, 20), (65, 0, 120))]
for f, loc, rot in keys:
    cam.location = loc; cam.rotation_euler = tuple(math.radians(a) for a in rot)
    cam.keyframe_insert('location', frame=f); cam.keyframe_insert('rotation_euler', frame=f)
truth = {"fps": 24, "fov_degrees": 50, "frames": []}
for f in range(1, 50):
    scene.frame_set(f)
    m = cam.matrix_world
    p = m.translation; fwd = -m.col[2].xyz; up = m.col[1].xyz
    yup = lambda v: [v.x, v.z, -v.y]   # Blender Z up -> glTF Y up
    truth["frames"].append({"frame": f, "position": yup(p), "forward": yup(fwd), "up": yup(up)})
json.dump(truth, open('blender-shot.json', 'w'), indent=1)
for name, sampled in (('blender-shot-sampled.glb', True), ('blender-shot-bezier.glb', False)):
    bpy.ops.export_scene.gltf(filepath=os.path.abspath(name), export_format='GLB', export_cameras=True,
                              export_animations=True, export_force_sampling=sampled, export_yup=True)
