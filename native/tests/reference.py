# Reference values for tests/test_unit.c, computed independently of the C code:
# xoshiro256** seeded with splitmix64 and the Irwin-Hall Gaussian of docs/ALGORITHM.md 1-2,
# multinomial resampling of seed 1, and the first particle of a known-pose init (seed 7).
# Run: python3 native/tests/reference.py
M=(1<<64)-1
def sm(st):
    st=(st+0x9E3779B97F4A7C15)&M; z=st
    z=((z^(z>>30))*0xBF58476D1CE4E5B9)&M
    z=((z^(z>>27))*0x94D049BB133111EB)&M
    return st, z^(z>>31)
def rotl(x,k): return ((x<<k)|(x>>(64-k)))&M
class R:
    def __init__(s,seed):
        st=seed&M; s.s=[]
        for i in range(4):
            st,z=sm(st); s.s.append(z)
    def next(s):
        s0,s1,s2,s3=s.s
        r=(rotl((s1*5)&M,7)*9)&M
        t=(s1<<17)&M
        s2^=s0; s3^=s1; s1^=s2; s0^=s3; s2^=t; s3=rotl(s3,45)
        s.s=[s0,s1,s2,s3]; return r
    def uniform(s): return (s.next()>>11)*2.0**-53
    def gauss(s):
        a=0.0
        for i in range(12): a=a+s.uniform()
        return a-6.0
for seed in (1,0,-1):
    r=R(seed); print(seed, [hex(x) for x in r.s])
    print(" next", [hex(r.next()) for i in range(3)])
    r=R(seed); print(" unif", [r.uniform().hex() for i in range(2)])
    r=R(seed); print(" gauss", [r.gauss().hex() for i in range(3)], [r.gauss() for i in range(0)])
r=R(1); w=[0.5,0.25,0.125,0.125]; cum=[0.5,0.75,0.875,1.0]
out=[]
for m in range(4):
    t=r.uniform()
    k=next((k for k in range(4) if t<cum[k]),3); out.append((k,t))
print(out)
# known init: first particle for seed 7, start (0.5,0.5,0.0)
r=R(7); g=[r.gauss() for i in range(3)]
import math
print("init", (0.5+0.05*g[0]).hex(), (0.5+0.05*g[1]).hex(), g[2])
